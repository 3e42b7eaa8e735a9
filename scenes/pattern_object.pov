// Tests the object pattern: a pigment list of two colours picked by the inside of a CSG object (moved with the
// pigment by its transforms), a pigment list of pigments, and a patterned texture choosing between two textures
// by the inside of a declared torus.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -8> look_at <0, 0.3, 0> angle 45 right x * 4 / 3 }
light_source { <-6, 10, -8> color rgb 1 }
#declare Blob = union { sphere { <0.3, 0, 0>, 0.55 } box { <-0.9, -0.2, -0.2>, <0.9, 0.2, 0.2> } }
plane { y, -1 pigment { object { Blob color rgb 0.8 color rgb <0.9, 0.2, 0.1> } scale 1.5 translate <0.5, -0.9, -2> } }
box { <-3.4, -1, -1>, <-1.4, 1, 1>
  pigment { object { Blob pigment { checker rgb 1 rgb 0.3 scale 0.2 } pigment { rgb <0.1, 0.5, 1> } }
    rotate y * 30 translate <-2.4, 0.4, -0.8> } }
#declare Ring = torus { 0.6, 0.25 rotate x * 90 }
sphere { <0, 0, 0>, 1
  texture { object { Ring texture { pigment { rgb <1, 0.9, 0.3> } finish { phong 0.8 } }
                          texture { pigment { rgb <0.2, 0.8, 0.3> } } }
    translate z * -0.8 } }
cylinder { <2.4, -1, 0>, <2.4, 1.2, 0>, 0.8
  pigment { object { difference { sphere { 0, 1 } sphere { 0, 0.7 } } rgb 0.2 rgb <1, 0.6, 0.1> }
    scale 0.9 translate <2.4, 0.5, -0.3> } }
