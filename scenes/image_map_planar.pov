// Tests image_map with the default planar mapping (map_type 0) on PNG images made by
// scripts/make_texture_images.py: nearest pixel, the image repeated and turned, `once` (clear outside the image,
// over a lower texture layer), `repeat` and `offset`, and the decoding of an sRGB image without chunks, one with a
// gAMA chunk of 1.0 and a 16-bit one with an sRGB chunk.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -10> look_at <0, 0, 0> angle 50 }
background { color rgb <0.2, 0.3, 0.4> }
light_source { <-10, 20, -30> color rgb <1, 1, 1> }
#declare Flat = finish { ambient 1 diffuse 0 }
#declare Tile = box { <0, 0, 0>, <1, 1, 0.1> }
object { Tile pigment { image_map { png "tex_rgb.png" } } finish { Flat }
  scale <2.6, 2.4, 1> translate <-4.3, 0.4, 0> }
object { Tile pigment { image_map { png "tex_rgb.png" } scale 0.4 rotate z * 25 }
  finish { ambient 0.3 diffuse 0.8 } scale <2.6, 2.4, 1> translate <-1.3, 0.4, 0> }
object { Tile
  texture { pigment { checker color rgb <0.9, 0.9, 0.9> color rgb <0.1, 0.1, 0.1> scale 0.25 } finish { Flat } }
  texture { pigment { image_map { "tex_rgb.png" once } scale 0.6 translate <0.2, 0.3, 0> } finish { Flat } }
  scale <2.6, 2.4, 1> translate <1.7, 0.4, 0> }
object { Tile pigment { image_map { png "tex_rgb.png" repeat <2, 1> offset <0.25, 0.5> } } finish { Flat }
  scale <2.6, 2.4, 1> translate <-4.3, -2.9, 0> }
object { Tile pigment { image_map { png "tex_linear.png" } } finish { Flat }
  scale <2.6, 2.4, 1> translate <-1.3, -2.9, 0> }
object { Tile pigment { image_map { png "tex_rgb16.png" } } finish { Flat }
  scale <2.6, 2.4, 1> translate <1.7, -2.9, 0> }
