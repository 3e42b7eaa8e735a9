// Tests image_map's cylindrical mapping (map_type 2): the angle around y and y itself (the image spanning
// 0 ≤ y < 1, repeated, or once), on cylinders, a sphere and a box.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -10> look_at <0, 0.3, 0> angle 45 }
background { color rgb <0.2, 0.3, 0.4> }
light_source { <-5, 10, -10> color rgb <1, 1, 1> }
#declare Card = pigment { image_map { png "tex_rgb.png" map_type 2 } }
cylinder { <0, -1, 0>, <0, 2, 0>, 1 pigment { Card } finish { ambient 0.4 diffuse 0.7 } translate <-3, 0, 0> }
cylinder { <0, 0, 0>, <0, 1, 0>, 1 pigment { Card rotate y * 45 } finish { ambient 1 diffuse 0 }
  scale <1, 2.5, 1> translate <0, -1, 0> }
cylinder { <0, -1, 0>, <0, 2, 0>, 1
  texture { pigment { rgb <0.6, 0.6, 0.6> } }
  texture { pigment { image_map { png "tex_rgb.png" map_type 2 once interpolate 2 } translate y * 0.2 } }
  translate <3, 0, 0> }
sphere { 0, 0.9 pigment { Card scale <1, 0.5, 1> } finish { ambient 1 diffuse 0 } translate <-1.5, 2.4, 1> }
box { -0.8, 0.8 pigment { Card } finish { ambient 1 diffuse 0 } rotate <20, 30, 0> translate <1.6, 2.4, 1> }
