// Tests the function pattern: user functions of x, y, z as pigment patterns (values above 1 wrapped, negative ones
// through the wave step), with a colour map, frequency and a sine wave, a declared function called from the pattern,
// a noise function, a function normal and a function-patterned texture_map.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "functions.inc"
camera { orthographic location <0, 0, -10> look_at 0 right x * 4 up y * 3 }
light_source { <-10, 10, -20> color rgb 1 }
#declare Ring = function(a, b, c) { sqrt(a * a + b * b) * 3 }
#macro Tile(T, Column, Row)
  box { <-0.48, -0.48, 0>, <0.48, 0.48, 1> texture { T } translate <Column - 1.5, 1 - Row, 0> }
#end
#declare Flat = finish { ambient 1 diffuse 0 }
Tile(texture { pigment { function { x * y * 8 } } finish { Flat } }, 0, 0)
Tile(texture { pigment { function { (x + y) * 3 - 1 } color_map { [0 rgb <1, 0.2, 0>] [1 rgb <0, 0.3, 1>] } }
  finish { Flat } }, 1, 0)
Tile(texture { pigment { function { Ring(x, y, z) } frequency 2 sine_wave } finish { Flat } }, 2, 0)
Tile(texture { pigment { function { f_noise3d(x * 6, y * 6, z) } color_map { [0.3 rgb 0] [0.7 rgb <1, 1, 0.5>] } }
  finish { Flat } }, 3, 0)
Tile(texture { pigment { function { abs(sin(x * 9) * cos(y * 7)) } poly_wave 2 } finish { Flat } }, 0, 1)
Tile(texture { pigment { rgb 0.8 } normal { function { f_noise3d(x * 8, y * 8, z * 8) } 0.8 }
  finish { ambient 0.1 diffuse 0.8 specular 0.5 } }, 1, 1)
Tile(texture { function { max(abs(x), abs(y)) * 4 } texture_map {
  [0.5 pigment { rgb <1, 0, 0> } finish { Flat }] [0.5 pigment { rgb <0, 0, 1> } finish { Flat }] } }, 2, 1)
Tile(texture { pigment { function { select(x, -1, 2) * y } } finish { Flat } }, 3, 1)
