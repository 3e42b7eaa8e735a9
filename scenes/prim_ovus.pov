// Tests ovus (POV-Ray 3.7's ovus.cpp): two spheres joined by a torus spindle. Left: bottom radius larger than the
// top one; middle: the top one larger (the other branch of Parse_Ovus), rotated and scaled; right: inside a
// difference (POV-Ray's inside test) with a box cut; the reflective floor shows their undersides.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -7> look_at <0, 0.9, 0> angle 45 }
light_source { <-4, 8, -6> color rgb 1 }
plane { y, 0 pigment { checker rgb 0.8 rgb 0.3 } finish { reflection 0.2 } }
ovus { 1, 0.6 pigment { rgb <0.9, 0.5, 0.2> } finish { phong 0.7 } translate <-2.2, 1, 0> }
ovus { 0.5, 0.8 pigment { rgb <0.2, 0.5, 0.9> } finish { phong 0.7 } rotate z*20 scale <1, 1.2, 1> translate <0, 0.6, 0.5> }
difference {
  ovus { 0.8, 1 }
  box { <-2, 0.5, -2>, <0, 3, 0> }
  pigment { rgb <0.3, 0.8, 0.3> } finish { phong 0.5 }
  translate <2.2, 0.8, 0>
}
