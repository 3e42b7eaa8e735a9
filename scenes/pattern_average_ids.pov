// Tests average (weighted mean of a pigment_map), pigment ids with copy-and-modify, and transforms on pigments.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -7> look_at <0, 0.5, 0> }
background { color rgb <0.1, 0.15, 0.25> }
light_source { <-4, 8, -6> color rgb <1, 1, 1> }
#declare Stripes = pigment { gradient x color_map { [0 rgb <1, 0, 0>] [0.5 rgb <1, 1, 0>] [1 rgb <1, 0, 0>] } }
#declare Rings = pigment { onion color_map { [0 rgb 0] [1 rgb <0, 0.8, 1>] } }
plane { y, 0 pigment { average pigment_map { [1 Stripes] [3 Rings scale 2] } } finish { ambient 1 diffuse 0 } }
sphere { <-1.3, 1, 0>, 0.9 pigment { Stripes rotate z*45 scale 0.5 frequency 2 } finish { ambient 1 diffuse 0 } }
sphere { <1.3, 1, 0>, 0.9 pigment { Rings radial frequency 4 } finish { ambient 1 diffuse 0 } }
