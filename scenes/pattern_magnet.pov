// Tests magnet: types 1 and 2 in their mandel and julia forms, with exterior and interior types, and in a
// texture_map.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 6, -8> look_at <0, 0.5, 0> }
background { color rgb <0.1, 0.15, 0.25> }
light_source { <-4, 8, -6> color rgb <1, 1, 1> }
#declare Map = color_map { [0 rgb <0.1, 0, 0.2>] [0.25 rgb <0.9, 0.3, 0.1>] [0.5 rgb <1, 1, 0.6>] [1 rgb <0.1, 0.4, 0.9>] }
plane { y, 0 pigment { magnet 1 mandel 40 color_map { Map } rotate x*90 scale 1.2 translate x*1.5 } finish { ambient 1 diffuse 0 } }
#declare Ball = sphere { 0, 0.7 }
object { Ball pigment { magnet 2 mandel 30 color_map { Map } scale 0.5 } finish { ambient 1 diffuse 0 } translate <-3, 0.7, 2> }
object { Ball pigment { magnet 1 julia <1.2, 0.4>, 30 color_map { Map } scale 0.6 } finish { ambient 1 diffuse 0 } translate <-1.5, 0.7, 2> }
object { Ball pigment { magnet 2 julia <0.8, 0.3>, 30 color_map { Map } scale 0.5 } finish { ambient 1 diffuse 0 } translate <0, 0.7, 2> }
object { Ball pigment { magnet 1 mandel 25 exterior 6, 0.01 interior 1, 1 color_map { Map } scale 0.5 } finish { ambient 1 diffuse 0 } translate <1.5, 0.7, 2> }
object { Ball pigment { magnet 2 mandel 25 exterior 3, 0.02 interior 2, 0.5 color_map { Map } scale 0.5 } finish { ambient 1 diffuse 0 } translate <3, 0.7, 2> }
object { Ball translate <-2, 0.7, 0>
  texture { magnet 1 mandel 20 scale 0.6
    texture_map { [0.3 pigment { rgb <0.2, 0.2, 0.8> } finish { phong 1 }] [0.7 pigment { rgb <1, 0.6, 0.1> } finish { ambient 0.6 }] } } }
