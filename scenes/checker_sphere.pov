// Tests the checker pigment on spheres (3-D checker cells cut by the surface), one scaled so the cells scale too.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -7> look_at <0, 1, 0> }
background { color rgb <0.1, 0.15, 0.25> }
light_source { <-4, 8, -6> color rgb <1, 1, 1> }
plane { y, -0.3 pigment { color rgb <0.6, 0.6, 0.6> } finish { ambient 0.1 diffuse 0.7 } }
sphere { <-1.6, 1.1, 0.3>, 1.3 pigment { checker color rgb <0.9, 0.2, 0.1>, color rgb <0.95, 0.9, 0.8> } finish { phong 0.5 } }
sphere { <0, 0, 0>, 1 pigment { checker color rgb <0.1, 0.3, 0.9>, color rgb <0.9, 0.9, 0.3> } scale 0.35 translate <1.8, 1.2, 0.2> finish { phong 0.5 } }
