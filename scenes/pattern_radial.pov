// Tests the radial pattern (angle around y, built-in cyan-yellow-magenta map) on a floor and a sphere.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -7> look_at <0, 0.5, 0> }
background { color rgb <0.1, 0.15, 0.25> }
light_source { <-4, 8, -6> color rgb <1, 1, 1> }
plane { y, 0 pigment { radial frequency 3 } finish { ambient 1 diffuse 0 } }
sphere { <0, 1, 0>, 1 pigment { radial color_map { [0 rgb 1] [0.5 rgb <0.8, 0.1, 0.1>] [1 rgb 0] } rotate x*90 } finish { ambient 0.3 diffuse 0.7 } }
