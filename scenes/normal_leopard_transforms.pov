// Tests a leopard normal and the normal transforms: a non-uniform scale and rotation (the normal goes into pattern
// space and back, normalised each way), no_bump_scale, and an object transform that moves its normal along.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -7> look_at <0, 0.6, 0> }
background { color rgb <0.1, 0.15, 0.25> }
light_source { <-4, 8, -6> color rgb <1, 1, 1> }
plane { y, 0 pigment { rgb 0.7 } normal { leopard 2 scale <0.2, 1, 0.5> rotate y*30 } }
sphere { 0, 1 pigment { rgb <0.9, 0.8, 0.3> } normal { leopard 0.4 scale 0.12 no_bump_scale }
         finish { phong 0.8 } translate <-1.3, 1, 0> }
sphere { 0, 1 pigment { rgb <0.4, 0.6, 0.9> } normal { radial 0.5 frequency 12 }
         scale <1, 0.6, 1> rotate x*-30 translate <1.3, 0.8, 0> }
