// Tests how image_map decodes PNG files in a scene with assumed_gamma 2.2: an RGB file without chunks (sRGB),
// one with a gAMA chunk of 1.0, a 16-bit one with an sRGB chunk, 8- and 16-bit greys, a palette image, and the
// `gamma 1.0` / `gamma srgb` overrides after the file name; all re-encoded into the working gamma 2.2.
#version 3.7;
global_settings { assumed_gamma 2.2 }
camera { location <0, 0, -10> look_at <0, 0, 0> angle 55 }
background { color rgb <0.2, 0.3, 0.4> }
#declare Flat = finish { ambient 1 diffuse 0 }
#declare Tile = box { <0, 0, 0>, <1, 1, 0.1> scale <2.2, 2, 1> }
object { Tile pigment { image_map { png "tex_rgb.png" } scale <2.2, 2, 1> } finish { Flat } translate <-4.8, 0.4, 0> }
object { Tile pigment { image_map { png "tex_linear.png" } scale <2.2, 2, 1> } finish { Flat } translate <-2.4, 0.4, 0> }
object { Tile pigment { image_map { png "tex_rgb16.png" } scale <2.2, 2, 1> } finish { Flat } translate <0, 0.4, 0> }
object { Tile pigment { image_map { png "tex_grey.png" } scale <2.2, 2, 1> } finish { Flat } translate <2.4, 0.4, 0> }
object { Tile pigment { image_map { png "tex_grey16.png" } scale <2.2, 2, 1> } finish { Flat } translate <-4.8, -2.4, 0> }
object { Tile pigment { image_map { png "tex_palette.png" } scale <2.2, 2, 1> } finish { Flat } translate <-2.4, -2.4, 0> }
object { Tile pigment { image_map { png "tex_rgb.png" gamma 1.0 } scale <2.2, 2, 1> } finish { Flat }
  translate <0, -2.4, 0> }
object { Tile pigment { image_map { png "tex_linear.png" gamma srgb } scale <2.2, 2, 1> } finish { Flat }
  translate <2.4, -2.4, 0> }
