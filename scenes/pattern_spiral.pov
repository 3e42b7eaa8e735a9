// Tests spiral1 and spiral2 (arms around the z axis, triangle wave by default), with other waves, a colour map,
// frequency, negative arm counts, classic turbulence (which these patterns also read inside) and as a normal.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0, 0, -10> look_at 0 right x * 4 up y * 3 }
light_source { <-10, 10, -20> color rgb 1 }
#macro Tile(T, Column, Row)
  box { <-0.48, -0.48, 0>, <0.48, 0.48, 1> texture { T } translate <Column - 1.5, 1 - Row, 0> }
#end
#declare Flat = finish { ambient 1 diffuse 0 }
#declare Map = color_map { [0 rgb <1, 0.9, 0.2>] [1 rgb <0.1, 0.2, 0.6>] }
Tile(texture { pigment { spiral1 3 color_map { Map } scale 0.2 } finish { Flat } }, 0, 0)
Tile(texture { pigment { spiral2 5 color_map { Map } scale 0.2 } finish { Flat } }, 1, 0)
Tile(texture { pigment { spiral1 -2 sine_wave frequency 2 color_map { Map } scale 0.3 } finish { Flat } }, 2, 0)
Tile(texture { pigment { spiral2 4.7 ramp_wave scale 0.25 } finish { Flat } }, 3, 0)
Tile(texture { pigment { spiral1 6 turbulence 0.3 color_map { Map } scale 0.3 } finish { Flat } }, 0, 1)
Tile(texture { pigment { spiral2 3 turbulence <0.5, 0.2, 0.2> octaves 3 color_map { Map } scale 0.3 } finish { Flat } }, 1, 1)
Tile(texture { pigment { rgb 0.8 } normal { spiral1 4 0.6 scale 0.2 } finish { ambient 0.1 diffuse 0.8 specular 0.4 } }, 2, 1)
Tile(texture { spiral2 2 texture_map { [0.5 pigment { rgb <1, 0, 0> } finish { Flat }] [0.5 pigment { rgb 1 } finish { Flat }] }
  scale 0.2 rotate x * 20 }, 3, 1)
