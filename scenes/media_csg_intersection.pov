// Tests media in an intersection: a lens (two overlapping spheres intersected) and a box clipped by a sphere, each
// hollow with glowing, absorbing media only inside the common part.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -7> look_at <0, 1.1, 0> }
background { color rgb <0.05, 0.05, 0.1> }
light_source { <-5, 10, -6> color rgb 0.8 }
plane { y, 0 pigment { checker color rgb 0.6 color rgb 0.1 } }
intersection {
  sphere { <-2.2, 1.3, 0>, 1.5 }
  sphere { <-0.4, 1.3, 0>, 1.5 }
  pigment { color rgbt <1, 1, 1, 1> } hollow
  interior { media { emission <0.3, 0.8, 0.4> absorption 0.4 } }
  rotate y*30 translate <-0.2, 0, 0>
}
intersection {
  box { <-1, -1, -1>, <1, 1, 1> }
  sphere { 0, 1.3 }
  pigment { color rgbt <1, 1, 1, 1> } hollow
  interior { media { emission <0.9, 0.4, 0.7> absorption 0.4 } }
  rotate <20, 30, 0> translate <1.6, 1.3, 0.3>
}
