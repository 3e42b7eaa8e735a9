// Tests hexagon: its default blue/green/red map on the floor, three written colours on a tilted floor patch.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -7> look_at <0, 0.5, 0> }
background { color rgb <0.1, 0.15, 0.25> }
light_source { <-4, 8, -6> color rgb <1, 1, 1> }
plane { y, 0 pigment { hexagon scale 0.6 } finish { ambient 1 diffuse 0 } }
box { <-1, 0.5, -1>, <1, 0.6, 1> pigment { hexagon color rgb <1, 1, 0.8>, color rgb <0.3, 0.3, 0.3> color rgb <0.8, 0.4, 0.1> scale 0.25 rotate y*20 } finish { ambient 1 diffuse 0 } rotate x*-20 translate <1.5, 0.5, 0> }
