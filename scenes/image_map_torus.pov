// Tests image_map's torus mapping (map_type 5): the angle around y and the angle around the tube of a torus of
// major radius 1, on tori of that radius and others, turned, with nearest pixels and interpolated.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -8> look_at <0, 0, 0> angle 45 }
background { color rgb <0.2, 0.3, 0.4> }
light_source { <-5, 10, -10> color rgb <1, 1, 1> }
#declare Card = pigment { image_map { png "tex_rgb.png" map_type 5 } }
torus { 1, 0.45 pigment { Card } finish { ambient 0.4 diffuse 0.7 } translate <-2, 0, 1> }
torus { 1, 0.45 pigment { image_map { png "tex_rgb.png" map_type 5 interpolate 2 } }
  finish { ambient 1 diffuse 0 } rotate <-60, 20, 0> translate <2, 0.3, 1> }
torus { 1.2, 0.3 pigment { Card } finish { ambient 1 diffuse 0 } translate <0, -0.2, -1.8> }
sphere { 0, 0.8 pigment { Card } finish { ambient 1 diffuse 0 } translate <0, 1.4, 1> }
