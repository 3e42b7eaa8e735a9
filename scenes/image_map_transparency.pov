// Tests image_map transparency: an RGBA image's alpha (transmit 1 − alpha), a palette image's tRNS entries,
// `transmit N, T` and `filter N, F` on palette entries, `filter all` / `transmit all` on palette and RGB images,
// clear pixels letting a lower texture layer and the light through (shadows filtered by the image).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -10> look_at <0, 0, 0> angle 50 }
background { color rgb <0.2, 0.3, 0.4> }
light_source { <-3, 8, -12> color rgb <1, 1, 1> }
plane { y, -3.2 pigment { checker color rgb <0.9, 0.9, 0.8> color rgb <0.3, 0.35, 0.4> } }
#declare Tile = box { <0, 0, 0>, <1, 1, 0.1> }
#declare Card = pigment { checker color rgb <1, 0.9, 0.2> color rgb <0.1, 0.2, 0.6> scale 0.125 }
object { Tile texture { pigment { Card } } texture { pigment { image_map { png "tex_rgba.png" } } }
  scale <2.6, 2.4, 1> translate <-4.3, 0.4, 0> }
object { Tile pigment { image_map { png "tex_palette.png" } }
  scale <2.6, 2.4, 1> translate <-1.3, 0.4, 0> }
object { Tile pigment { image_map { png "tex_palette.png" transmit 0, 0.6 filter 4, 1 transmit 3, 0.2 } }
  scale <2.6, 2.4, 1> translate <1.7, 0.4, 0> }
object { Tile pigment { image_map { png "tex_palette.png" filter all 0.7 transmit 1, 0.5 } }
  scale <2.6, 2.4, 1> translate <-4.3, -2.9, 0> }
object { Tile pigment { image_map { png "tex_rgb.png" transmit all 0.5 } }
  scale <2.6, 2.4, 1> translate <-1.3, -2.9, 0> }
object { Tile pigment { image_map { png "tex_rgb.png" filter all 0.8 } } finish { phong 0.6 }
  scale <2.6, 2.4, 1> translate <1.7, -2.9, 0> }
