// Tests normal_map (a pattern choosing and blending whole normals), the normals of a list pattern (hexagon with
// normal { } entries), an average of normals with weights, a declared normal in a map entry, and a
// normal_map inside a transformed normal.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -9> look_at <0, 0.6, 0> angle 50 }
background { color rgb <0.1, 0.15, 0.25> }
light_source { <-5, 8, -6> color rgb <1, 1, 1> }
light_source { <6, 4, -5> color rgb <0.4, 0.4, 0.45> }
plane { y, -1 pigment { color rgb <0.8, 0.8, 0.75> }
  normal { hexagon normal { bumps 0.6 scale 0.2 }, normal { dents 0.8 scale 0.3 }, normal { wrinkles 0.5 scale 0.4 }
    scale 0.8 } }
#declare Ripply = normal { ripples 0.8 frequency 6 }
sphere { <-2.4, 0.5, 0>, 1.2 pigment { color rgb <0.9, 0.5, 0.3> } finish { phong 0.6 }
  normal { gradient y normal_map { [0.3 bumps 0.7 scale 0.15] [0.5 Ripply] [0.7 wrinkles 0.9 scale 0.3] } } }
sphere { <0, 0.5, 0>, 1.2 pigment { color rgb <0.4, 0.8, 0.5> } finish { phong 0.6 }
  normal { average normal_map { [1 bumps 0.8 scale 0.2] [2 waves 0.6 frequency 4] [dents 1 scale 0.25] } } }
sphere { <2.4, 0.5, 0>, 1.2 pigment { color rgb <0.4, 0.6, 0.95> } finish { phong 0.6 }
  normal { radial frequency 6 normal_map { [0 quilted 0.8 scale 0.2] [0.5 bumps 0.5 scale 0.1] [1 quilted 0.8 scale 0.2] }
    rotate 90*x scale 1.2 } }
