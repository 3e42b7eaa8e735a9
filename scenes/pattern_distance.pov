// Tests the distance patterns planar, boxed, spherical and cylindrical (1 at the centre falling to 0 at 1).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -7> look_at <0, 0.5, 0> }
background { color rgb <0.1, 0.15, 0.25> }
light_source { <-4, 8, -6> color rgb <1, 1, 1> }
#declare Map = color_map { [0 rgb <0.05, 0.05, 0.2>] [0.5 rgb <0.2, 0.7, 0.3>] [1 rgb <1, 0.95, 0.6>] }
plane { y, 0 pigment { boxed color_map { Map } scale 2.5 } finish { ambient 1 diffuse 0 } }
sphere { <-2.2, 1, 0>, 0.9 pigment { planar color_map { Map } scale 0.7 } finish { ambient 1 diffuse 0 } }
sphere { <0, 1, 0>, 0.9 pigment { spherical color_map { Map } translate <0.4, 1.5, -0.5> } finish { ambient 1 diffuse 0 } }
sphere { <2.2, 1, 0>, 0.9 pigment { cylindrical color_map { Map } scale 0.8 translate <2.2, 0, -0.3> } finish { ambient 1 diffuse 0 } }
