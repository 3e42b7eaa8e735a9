// Tests pigment_map (blended pigments, nested patterns in the outer pattern's space) and checker with pigment entries.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -7> look_at <0, 0.5, 0> }
background { color rgb <0.1, 0.15, 0.25> }
light_source { <-4, 8, -6> color rgb <1, 1, 1> }
plane { y, 0 pigment { checker pigment { gradient x color_map { [0 rgb <1, 0.9, 0.5>] [1 rgb <0.6, 0.2, 0>] } } pigment { rgb <0.1, 0.2, 0.4> } scale 1.5 } finish { ambient 1 diffuse 0 } }
sphere { <0, 1, 0>, 1 pigment { gradient y pigment_map { [0.2 checker rgb 1, rgb 0 scale 0.25] [0.5 rgb <1, 0.3, 0>] [0.8 hexagon scale 0.15] } scale 2 translate -y } finish { ambient 1 diffuse 0 } }
