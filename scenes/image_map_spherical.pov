// Tests image_map's spherical mapping (map_type 1): longitude from +x towards +z, latitude from the south to the
// north pole, on spheres seen from several sides, one turned and scaled, one interpolated, one image used once.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -9> look_at <0, 0, 0> angle 45 }
background { color rgb <0.2, 0.3, 0.4> }
light_source { <-5, 10, -10> color rgb <1, 1, 1> }
#declare Card = pigment { image_map { png "tex_rgb.png" map_type 1 } }
sphere { 0, 1.3 pigment { Card } finish { ambient 0.4 diffuse 0.7 } translate <-2.4, 0.9, 0> }
sphere { 0, 1.3 pigment { Card rotate <30, 60, 0> } finish { ambient 1 diffuse 0 } translate <0.4, 0.9, 0> }
sphere { 0, 1 pigment { image_map { png "tex_rgb.png" map_type 1 interpolate 2 } }
  finish { ambient 1 diffuse 0 } scale <1.2, 0.8, 1.2> rotate y * -90 translate <2.9, 1.2, -0.5> }
sphere { 0, 1.2 texture { pigment { rgb <0.7, 0.7, 0.7> } }
  texture { pigment { image_map { png "tex_rgb.png" map_type 1 once } scale 1.5 } finish { phong 0.8 } }
  rotate x * -90 translate <-1.2, -1.6, 0> }
sphere { 0, 1.2 pigment { image_map { png "tex_palette.png" map_type 1 } rotate y * 200 }
  finish { ambient 0.6 diffuse 0.5 } translate <1.8, -1.6, 0> }
