// Tests image_map without gamma handling: no #version and no assumed_gamma (POV-Ray 3.62 rules) read the stored
// numbers as they are, whatever the file's chunks say.
global_settings { max_trace_level 5 }
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
