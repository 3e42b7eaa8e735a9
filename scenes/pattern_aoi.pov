// Tests aoi: the angle between the surface normal (facing the ray, bent by a normal) and the ray, 0 … 1, on primary
// rays, in a reflection and seen through a transparent object.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -7> look_at <0, 0.8, 0> }
background { color rgb <0.1, 0.15, 0.25> }
light_source { <-4, 8, -6> color rgb <1, 1, 1> }
#declare Map = color_map { [0.5 rgb <1, 1, 0.2>] [0.75 rgb <0.8, 0.2, 0.1>] [1 rgb <0.1, 0.1, 0.5>] }
plane { y, 0 pigment { checker rgb 0.8, rgb 0.3 } }
sphere { <-2, 1, 0>, 1 pigment { aoi color_map { Map } } finish { ambient 1 diffuse 0 } }
sphere { <0.2, 1, 0>, 1 pigment { aoi color_map { Map } } normal { bumps 0.6 scale 0.2 } finish { ambient 1 diffuse 0 } }
sphere { <2.3, 1, 1>, 1 pigment { rgb 0.1 } finish { reflection 0.8 ambient 0 diffuse 0.2 } }
box { <-1, 0, -2.5>, <1, 0.6, -2.4> pigment { aoi color_map { [0 rgbt <1, 1, 1, 0.9>] [1 rgbt <1, 0, 0, 0.2>] } } }
