// Tests non-uniform scale of spheres (ellipsoids): shading normals must use the inverse transpose, highlights follow.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -7> look_at <0, 1, 0> }
background { color rgb <0.1, 0.15, 0.25> }
light_source { <-4, 7, -6> color rgb <1, 1, 1> }
plane { y, 0 pigment { color rgb <0.8, 0.8, 0.7> } finish { ambient 0.1 diffuse 0.7 } }
sphere { <0, 0, 0>, 1 scale <1.6, 0.6, 1> translate <-2, 0.6, 0> pigment { color rgb <0.9, 0.3, 0.2> } finish { phong 0.8 phong_size 30 } }
sphere { <0, 1, 0>, 1 scale <0.5, 1.5, 0.5> pigment { color rgb <0.2, 0.8, 0.3> } finish { specular 0.7 roughness 0.02 } }
sphere { <0, 0, 0>, 1 scale <0.6, 1.2, 0.6> rotate z*35 translate <2.2, 1.1, 0> pigment { color rgb <0.3, 0.4, 0.9> } finish { phong 0.8 phong_size 30 } }
