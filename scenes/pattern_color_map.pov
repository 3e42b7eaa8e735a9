// Tests color_map forms: new and old-style entries, hard edges, filter/transmit interpolation, a declared map.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -7> look_at <0, 0.5, 0> }
background { color rgb <0.1, 0.15, 0.25> }
light_source { <-4, 8, -6> color rgb <1, 1, 1> }
#declare Declared = colour_map { [0.0 color rgb <1, 0, 0>] [0.3 color rgb <1, 1, 0>] [0.3 color rgb <0, 0.6, 0>] [1.0 color rgb <0, 0, 1>] }
plane { y, 0 pigment { gradient x color_map { Declared } scale 3 translate -1.5*x } finish { ambient 1 diffuse 0 } }
sphere { <-1.5, 1, 0>, 0.9 pigment { gradient y color_map { [0.0, 0.5 color rgb <1, 0.5, 0> color rgb <0, 0.5, 1>] [0.5, 1.0 color rgb 1 color rgb 0] } scale 2 translate -y } finish { ambient 1 diffuse 0 } }
sphere { <1.5, 1, 0>, 0.9 pigment { gradient z color_map { [0.2 rgbt <1, 1, 1, 1>] [0.8 rgbf <1, 0.2, 0.2, 0.8>] } scale 1.8 translate -0.9*z } finish { ambient 1 diffuse 0 } }
