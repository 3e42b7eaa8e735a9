// Tests mandel: the default exterior (iterations as a fraction) on a floor, exponents 3, 4 and 7 (POV-Ray's
// binomial expansion), and every interior type on spheres: POV-Ray 3.7 evaluates the pattern in the complex plane of
// the pattern's x and y; the built-in map of the exponent-2 mandel (cyan, yellow, magenta near the set).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 6, -8> look_at <0, 0.5, 0> }
background { color rgb <0.1, 0.15, 0.25> }
light_source { <-4, 8, -6> color rgb <1, 1, 1> }
#declare Map = color_map { [0 rgb <0, 0, 0.3>] [0.2 rgb <0.2, 0.6, 1>] [0.5 rgb <1, 1, 0.4>] [1 rgb <0.6, 0, 0>] }
plane { y, 0 pigment { mandel 40 color_map { Map } rotate x*90 scale 2.5 translate x*1.2 } finish { ambient 1 diffuse 0 } }
#declare Ball = sphere { 0, 0.7 }
object { Ball pigment { mandel 30 exponent 3 color_map { Map } } finish { ambient 1 diffuse 0 } translate <-3, 0.7, 2> }
object { Ball pigment { mandel 30 exponent 4 color_map { Map } } finish { ambient 1 diffuse 0 } translate <-1.5, 0.7, 2> }
object { Ball pigment { mandel 20 exponent 7 color_map { Map } scale 0.8 } finish { ambient 1 diffuse 0 } translate <0, 0.7, 2> }
object { Ball pigment { mandel 25 interior 1, 2 color_map { Map } } finish { ambient 1 diffuse 0 } translate <1.5, 0.7, 2> }
object { Ball pigment { mandel 25 interior 6, 0.5 exterior 6, 0.2 color_map { Map } } finish { ambient 1 diffuse 0 } translate <3, 0.7, 2> }
object { Ball pigment { mandel 25 interior 2, 1 exterior 2, 0.3 color_map { Map } } finish { ambient 1 diffuse 0 } translate <-3, 0.7, 0> }
object { Ball pigment { mandel 25 interior 3, 1 exterior 3, 0.3 color_map { Map } } finish { ambient 1 diffuse 0 } translate <-1.5, 0.7, 0> }
object { Ball pigment { mandel 25 interior 4, 2 exterior 4, 0.1 color_map { Map } } finish { ambient 1 diffuse 0 } translate <1.5, 0.7, 0> }
object { Ball pigment { mandel 25 interior 5, 2 exterior 5, 0.1 color_map { Map } } finish { ambient 1 diffuse 0 } translate <3, 0.7, 0> }
object { Ball pigment { mandel 60 scale 0.8 translate -x*0.3 } finish { ambient 1 diffuse 0 } translate <0, 0.7, 0> }
