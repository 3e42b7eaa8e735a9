// Tests a height_field read from a palette PNG (height_field_palette.png, 24 x 18, 8-bit indices; written by
// scripts/make_texture_images.py): POV-Ray takes each pixel's palette index · 256 as its height, not the colour
// (the palette runs from white at index 0 to black at 255). Flat and smooth, one cut by water_level.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -8> look_at <0, 0.4, 0> }
background { color rgb <0.1, 0.15, 0.25> }
light_source { <-4, 8, -5> color rgb <1, 1, 1> }
light_source { <6, 3, -3> color rgb <0.3, 0.3, 0.4> }
plane { y, 0 pigment { checker color rgb <0.8, 0.8, 0.7> color rgb <0.5, 0.5, 0.45> } }
height_field { png "height_field_palette.png"
  translate <-0.5, 0, -0.5> scale <3, 1.2, 3> translate <-1.8, 0, 0.5>
  pigment { color rgb <0.9, 0.5, 0.3> } finish { phong 0.4 } }
height_field { png "height_field_palette.png" smooth water_level 0.3
  translate <-0.5, 0, -0.5> scale <3, 1.2, 3> rotate y * 30 translate <1.8, 0, 0.5>
  pigment { color rgb <0.3, 0.8, 0.4> } finish { phong 0.4 } }
