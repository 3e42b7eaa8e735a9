// Tests pigment functions (function { pigment { … } }) evaluated while rendering: a pigment's function pattern that
// reads their channels, and an isosurface displaced by one's gray.
#version 3.7;
#declare P = function { pigment { wood turbulence 0.3 color_map { [0 rgb <1,0.2,0>] [1 rgbt <0,0.4,1,0.5>] } scale 0.4 } }
#declare G = function { pigment { granite pigment_map { [0 rgb 1] [1 gradient y color_map { [0 rgb 0] [1 rgb <0,1,0>] }] } scale 0.6 } }
camera { location <0, 2, -5> look_at 0 }
light_source { <-5, 10, -10>, rgb 1 }
plane { y, -1 pigment { function { P(x, y, z).red * 0.6 + P(x, y, z).transmit } color_map { [0 rgb <1,0.5,0>] [1 rgb <0,0.3,1>] } } }
isosurface { function { sqrt(x*x+y*y+z*z) - 1 + G(x, y, z).gray*0.3 } contained_by { sphere { 0, 1.5 } } max_gradient 3
  pigment { rgb 1 } }
