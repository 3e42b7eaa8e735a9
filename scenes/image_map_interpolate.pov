// Tests image_map interpolation: bilinear (interpolate 2), bicubic (3) and normalised distance (4) on an enlarged
// 8 x 6 card, the image wrapping at its edges, and `once` clamping the neighbours of edge pixels instead; then the
// same on a palette image.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -10> look_at <0, 0, 0> angle 50 }
background { color rgb <0.2, 0.3, 0.4> }
#declare Flat = finish { ambient 1 diffuse 0 }
#declare Tile = box { <0, 0, 0>, <1, 1, 0.1> }
object { Tile pigment { image_map { png "tex_rgb.png" interpolate 2 } } finish { Flat }
  scale <2.6, 2.4, 1> translate <-4.3, 0.4, 0> }
object { Tile pigment { image_map { png "tex_rgb.png" interpolate 3 } } finish { Flat }
  scale <2.6, 2.4, 1> translate <-1.3, 0.4, 0> }
object { Tile pigment { image_map { png "tex_rgb.png" interpolate 4 } } finish { Flat }
  scale <2.6, 2.4, 1> translate <1.7, 0.4, 0> }
object { Tile pigment { image_map { png "tex_rgb.png" interpolate 2 once } scale 0.8 translate 0.1 }
  finish { Flat } scale <2.6, 2.4, 1> translate <-4.3, -2.9, 0> }
object { Tile pigment { image_map { png "tex_palette.png" interpolate 2 } } finish { Flat }
  scale <2.6, 2.4, 1> translate <-1.3, -2.9, 0> }
object { Tile pigment { image_map { png "tex_rgb.png" interpolate 3 once } scale 0.8 translate 0.1 }
  finish { Flat } scale <2.6, 2.4, 1> translate <1.7, -2.9, 0> }
