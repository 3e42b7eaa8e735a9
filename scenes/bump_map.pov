// Tests bump_map: the slope of an image's grey (8- and 16-bit grey PNGs, read without gamma handling) bends the
// normal, with bump_size, interpolate 2, once, the planar and spherical mappings and palette indices (use_index).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 6, -8> look_at <0, 0, 0> angle 50 }
background { color rgb <0.2, 0.3, 0.4> }
light_source { <-6, 12, -4> color rgb <1, 1, 1> }
#declare Tile = box { <0, 0, 0>, <1, 1, 0.1> }
#declare Paint = texture { pigment { color rgb <0.9, 0.8, 0.6> } finish { phong 0.6 } }
object { Tile texture { Paint normal { bump_map { png "tex_grey.png" bump_size 3 } } }
  scale <2.6, 2.4, 1> rotate x * 90 translate <-4.3, 0, 2> }
object { Tile texture { Paint normal { bump_map { png "tex_grey16.png" interpolate 2 } 2 } }
  scale <2.6, 2.4, 1> rotate x * 90 translate <-1.3, 0, 2> }
object { Tile texture { Paint normal { bump_map { png "tex_palette.png" use_index bump_size 0.3 } } }
  scale <2.6, 2.4, 1> rotate x * 90 translate <1.7, 0, 2> }
object { Tile texture { Paint normal { bump_map { png "tex_grey.png" once bump_size 2 } scale 0.5 translate 0.25 } }
  scale <2.6, 2.4, 1> rotate x * 90 translate <-4.3, 0, -1.5> }
sphere { 0, 1.2 texture { Paint normal { bump_map { png "tex_grey.png" map_type 1 interpolate 2 bump_size 4 } } }
  translate <0, 1.2, -1> }
object { Tile texture { Paint normal { bump_map { png "tex_rgb.png" bump_size 1.5 } rotate z * 20 } }
  scale <2.6, 2.4, 1> rotate x * 90 translate <1.7, 0, -1.5> }
