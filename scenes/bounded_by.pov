// Tests bounded_by: a union bounded by a box too small for it (rays missing the bound see nothing of it, rays
// starting inside see it all), an intersection bounded by a sphere that encloses it (no visible change), and a
// bound on a plain sphere, which POV-Ray removes ("Unnecessary bounding object removed") but whose bounding box
// it keeps: rays missing that box miss the sphere, which cuts its left side off.
// The cut union casts no shadow: POV-Ray's shadow cache retests the last occluding child of a union without the
// union's bound, so where a bound cuts an object its shadow depends on POV-Ray's pixel order and threads.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -7.5> look_at <0, 0.8, 0> }
background { color rgb <0.1, 0.15, 0.25> }
light_source { <-4, 8, -6> color rgb 1 }
light_source { <5, 4, -5> color rgb 0.35 }
plane { y, 0 pigment { checker rgb 0.9 rgb 0.6 } }
union {
  sphere { <-2.9, 1, 0>, 0.8 }
  sphere { <-1.7, 1, 0>, 0.8 }
  bounded_by { box { <-3.7, 0.2, -0.8>, <-1.9, 1.3, 0.8> } }
  pigment { rgb <0.9, 0.4, 0.3> }
  no_shadow
}
intersection {
  box { <-0.8, 0, -0.8>, <0.8, 1.6, 0.8> }
  sphere { <0, 0.8, 0>, 1.05 }
  bounded_by { sphere { <0, 0.8, 0>, 1.5 } }
  pigment { rgb <0.3, 0.5, 0.9> }
}
sphere {
  <2.4, 1, 0>, 1
  bounded_by { box { <2, 0, -1>, <3.4, 2, 1> } }
  pigment { rgb <0.4, 0.9, 0.4> }
}
