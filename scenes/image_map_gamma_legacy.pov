// Tests image_map decoding in a #version 3.6 scene with assumed_gamma 2.2: POV-Ray takes a PNG without chunks to be
// in the working gamma already (no change), decodes one with a gAMA or sRGB chunk by it and re-encodes it, and a
// `gamma 2.2` override decodes with 2.2.
#version 3.6;
global_settings { assumed_gamma 2.2 }
camera { location <0, 0, -10> look_at <0, 0, 0> angle 55 }
background { color rgb <0.2, 0.3, 0.4> }
#declare Flat = finish { ambient 1 diffuse 0 }
#declare Tile = box { <0, 0, 0>, <1, 1, 0.1> scale <2.2, 2, 1> }
object { Tile pigment { image_map { png "tex_rgb.png" } scale <2.2, 2, 1> } finish { Flat } translate <-4.8, 0.4, 0> }
object { Tile pigment { image_map { png "tex_linear.png" } scale <2.2, 2, 1> } finish { Flat } translate <-2.4, 0.4, 0> }
object { Tile pigment { image_map { png "tex_rgb16.png" } scale <2.2, 2, 1> } finish { Flat } translate <0, 0.4, 0> }
object { Tile pigment { image_map { png "tex_grey.png" } scale <2.2, 2, 1> } finish { Flat } translate <2.4, 0.4, 0> }
object { Tile pigment { image_map { png "tex_palette.png" } scale <2.2, 2, 1> } finish { Flat }
  translate <-2.4, -2.4, 0> }
object { Tile pigment { image_map { png "tex_rgb.png" gamma 2.2 } scale <2.2, 2, 1> } finish { Flat }
  translate <0, -2.4, 0> }
