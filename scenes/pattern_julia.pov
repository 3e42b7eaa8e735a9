// Tests julia: the complex constant, exponents 2, 3, 4 and 9, exterior types 0, 7 and 8, and a julia normal.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 6, -8> look_at <0, 0.5, 0> }
background { color rgb <0.1, 0.15, 0.25> }
light_source { <-4, 8, -6> color rgb <1, 1, 1> }
#declare Map = color_map { [0 rgb <0, 0, 0.3>] [0.3 rgb <0.2, 0.8, 0.5>] [0.6 rgb <1, 0.9, 0.4>] [1 rgb <0.7, 0.1, 0.2>] }
plane { y, 0 pigment { julia <-0.745, 0.11>, 60 color_map { Map } rotate x*90 scale 2.5 } finish { ambient 1 diffuse 0 } }
#declare Ball = sphere { 0, 0.7 }
object { Ball pigment { julia <0.285, 0.01>, 40 exponent 3 color_map { Map } } finish { ambient 1 diffuse 0 } translate <-3, 0.7, 2> }
object { Ball pigment { julia <0.4, 0.3>, 40 exponent 4 color_map { Map } } finish { ambient 1 diffuse 0 } translate <-1.5, 0.7, 2> }
object { Ball pigment { julia <0.6, 0.2>, 30 exponent 9 color_map { Map } } finish { ambient 1 diffuse 0 } translate <0, 0.7, 2> }
object { Ball pigment { julia <-0.8, 0.156>, 50 exterior 7, 5 color_map { Map } } finish { ambient 1 diffuse 0 } translate <1.5, 0.7, 2> }
object { Ball pigment { julia <-0.8, 0.156>, 50 exterior 8, 4 interior 0, 0.5 color_map { Map } } finish { ambient 1 diffuse 0 } translate <3, 0.7, 2> }
object { Ball pigment { julia <-0.4, 0.6>, 30 exterior 0, 0.8 interior 1, 1 color_map { Map } } finish { ambient 1 diffuse 0 } translate <-2, 0.7, 0> }
object { Ball pigment { rgb <1, 0.8, 0.6> } normal { julia <0.355, 0.355>, 30 1.5 scale 0.7 } finish { ambient 0.2 diffuse 0.8 phong 0.5 } translate <0, 0.7, 0> }
object { Ball pigment { julia <-0.4, 0.6>, 30 exponent 1 color_map { Map } } finish { ambient 1 diffuse 0 } translate <2, 0.7, 0> }
