// Tests the torus: flat, standing, one seen edge-on, a thin one, a scaled one, and one solved with sturm.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -9> look_at <0, 1, 0> }
background { color rgb <0.1, 0.15, 0.25> }
light_source { <-4, 8, -5> color rgb <1, 1, 1> }
light_source { <6, 3, -3> color rgb <0.3, 0.3, 0.4> }
plane { y, 0 pigment { checker color rgb <0.8, 0.8, 0.7> color rgb <0.5, 0.5, 0.45> } }
torus { 1, 0.3 translate <-3, 0.3, 0> pigment { color rgb <0.9, 0.3, 0.2> } finish { phong 0.5 } }
torus { 0.9, 0.25 rotate x * 90 translate <0, 1.15, 0.5> pigment { color rgb <0.2, 0.8, 0.3> } finish { phong 0.5 } }
// Edge-on: the camera lies in the torus's plane.
torus { 0.8, 0.2 rotate x * 17.28 translate <3, 1.2, 0> pigment { color rgb <0.3, 0.4, 0.9> } finish { specular 0.4 } }
torus { 1.2, 0.05 sturm translate <0, 0.05, -2.5> pigment { color rgb <0.9, 0.8, 0.2> } }
torus { 0.6, 0.3 scale <1, 2, 1> rotate z * 30 translate <-2, 1.6, 2.5> pigment { color rgb <0.8, 0.4, 0.8> } }
