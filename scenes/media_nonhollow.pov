// Tests media in an object that is not hollow: POV-Ray 3.7.0.10 computes no media (neither the object's own nor
// atmospheric) along a ray that is inside any non-hollow object (render/ray.cpp hollowRay, trace.cpp: media only if
// ray.IsHollowRay()), so the left sphere, transparent and not hollow, shows nothing of its emitting media, while
// the right sphere, the same but hollow, glows. The middle box is not hollow and holds a hollow sphere with media:
// rays inside the box are not hollow rays, so that sphere's media is not seen either. No warning.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -7> look_at <0, 1, 0> }
background { color rgb <0.05, 0.05, 0.1> }
light_source { <-5, 10, -6> color rgb 0.8 }
plane { y, 0 pigment { checker color rgb 0.6 color rgb 0.1 } }
sphere { <-2.2, 1, 0>, 1 pigment { color rgbt <1, 1, 1, 1> }
  interior { media { emission <0.8, 0.4, 0.1> } } }
box { <-1, 0.01, -1>, <1, 2, 1> pigment { color rgbt <1, 1, 1, 0.8> } rotate y*20 }
sphere { <0, 1, 0>, 0.7 pigment { color rgbt <1, 1, 1, 1> } hollow
  interior { media { emission <0.3, 0.8, 0.2> } } }
sphere { <2.2, 1, 0>, 1 pigment { color rgbt <1, 1, 1, 1> } hollow
  interior { media { emission <0.8, 0.4, 0.1> } } }
