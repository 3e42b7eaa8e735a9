// Tests image_pattern (POV-Ray's Parse_Image_Pattern and imageutil.cpp image_pattern): the image is read without
// gamma handling; the value is its grey 0.297 R + 0.589 G + 0.114 B (left: an RGB image through a colour_map,
// interpolated), with use_alpha its transmit (middle: an RGBA image), the red of an image without alpha with
// use_alpha (the palette image, right, `once`: 0 off the image), and as a normal pattern (the floor, bumps
// by the grey image, map_type 0 repeated).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -5> look_at <0, 0.6, 0> angle 50 }
light_source { <-3, 6, -5> color rgb 1 }
plane { y, 0
  pigment { rgb 0.7 }
  normal { image_pattern { png "tex_grey.png" interpolate 2 } 0.8 scale 0.5 rotate x*90 } }
box { <-2.4, 0, 0>, <-0.9, 1.5, 0.1>
  pigment { image_pattern { png "tex_rgb.png" interpolate 2 }
            colour_map { [0 rgb <0.1, 0, 0.3>] [0.5 rgb <0.9, 0.5, 0.1>] [1 rgb 1] }
            scale 1.5 translate <-2.4, 0, 0> } }
box { <-0.75, 0, 0>, <0.75, 1.5, 0.1>
  pigment { image_pattern { png "tex_rgba.png" use_alpha }
            colour_map { [0 rgb <0, 0.4, 0>] [1 rgb <1, 1, 0.6>] }
            scale 1.5 translate <-0.75, 0, 0> } }
box { <0.9, 0, 0>, <2.4, 1.5, 0.1>
  pigment { image_pattern { png "tex_palette.png" use_alpha once }
            colour_map { [0 rgb <0.2, 0.2, 0.6>] [1 rgb <1, 0.3, 0.2>] }
            scale 1 translate <1.1, 0.2, 0> } }
