// Tests list patterns used as normals (no normal entries: the pattern value's slope bends the normal only near
// the cell borders): checker on a floor, hexagon on a sphere, brick with accuracy on a box.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -7> look_at <0, 0.6, 0> }
background { color rgb <0.1, 0.15, 0.25> }
light_source { <-4, 8, -6> color rgb <1, 1, 1> }
plane { y, 0 pigment { rgb 0.8 } normal { checker 1 } finish { phong 0.5 } }
sphere { <-1.2, 1, 0>, 1 pigment { rgb <0.3, 0.8, 0.4> } normal { hexagon 0.6 scale 0.25 } }
box { <0.4, 0, -0.8>, <2.2, 1.6, 0.8> rotate y*-20 pigment { rgb <0.9, 0.5, 0.3> }
      normal { brick bump_size 2 brick_size <0.5, 0.25, 0.5> mortar 0.05 accuracy 0.05 } }
