// Tests pigment_pattern: a pigment's grey (0.297 R + 0.589 G + 0.114 B, single precision) as a pattern value, in a
// pigment with its own map, a normal, a patterned texture and a pattern function; an image map used once gives 0
// off the image (no colour found).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -7> look_at <0, 0.6, 0> }
background { color rgb <0.1, 0.15, 0.25> }
light_source { <-4, 8, -6> color rgb <1, 1, 1> }
#declare Checks = pigment { checker rgb <1, 0.2, 0.2>, rgb <0.1, 0.3, 1> scale 0.5 }
#declare Map = color_map { [0 rgb <0, 0, 0.4>] [0.5 rgb <1, 0.8, 0.2>] [1 rgb <0.8, 0, 0>] }
plane { y, 0 pigment { pigment_pattern { bozo color_map { [0 rgb 0] [1 rgb <1, 0.5, 0>] } scale 0.6 } color_map { Map } } }
sphere { <-2.4, 1, 0>, 0.9 pigment { pigment_pattern { Checks } color_map { Map } } finish { ambient 1 diffuse 0 } }
sphere { <-0.6, 1, 0>, 0.7 pigment { rgb <1, 0.9, 0.7> } normal { pigment_pattern { granite } 1 scale 0.8 } }
sphere { <1, 1, 0>, 0.7
  texture { pigment_pattern { gradient y color_map { [0 rgb 0] [1 rgb 1] } scale 2 translate -y }
    texture_map { [0.4 pigment { rgb <0.2, 0.6, 0.2> } finish { ambient 1 diffuse 0 }] [0.6 pigment { rgb 1 } finish { ambient 1 diffuse 0 }] } }
  translate y }
#declare F = function { pattern { pigment_pattern { spotted color_map { [0 rgb <0.2, 0.1, 0>] [1 rgb <1, 1, 0.4>] } } } }
sphere { <2.5, 1, 0>, 0.8 pigment { function { F(x * 3, y * 3, z * 3) } color_map { Map } } finish { ambient 1 diffuse 0 } }
box { <-1.5, 0, 1.5>, <1.5, 1.5, 1.7> pigment { pigment_pattern { image_map { png "tex_rgb.png" once } } color_map { Map } } finish { ambient 1 diffuse 0 } }
