// Tests the superellipsoid: a rounded box, a pinched star (exponents above 2), a sphere-like one, a cylinder-like
// one, a thin disc-like one, transformed ones and one with equal exponents written as a single float.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -9> look_at <0, 1, 0> }
background { color rgb <0.1, 0.15, 0.25> }
light_source { <-4, 8, -5> color rgb <1, 1, 1> }
light_source { <6, 3, -3> color rgb <0.3, 0.3, 0.4> }
plane { y, 0 pigment { checker color rgb <0.8, 0.8, 0.7> color rgb <0.5, 0.5, 0.45> } }
superellipsoid { <0.25, 0.25> translate <-3, 1, 0> pigment { color rgb <0.9, 0.3, 0.2> } finish { phong 0.5 } }
superellipsoid { <2.5, 2.5> scale 1.2 translate <0, 1.2, 1> pigment { color rgb <0.2, 0.8, 0.3> } finish { phong 0.5 } }
superellipsoid { 1 scale 0.7 translate <3, 0.7, 0> pigment { color rgb <0.3, 0.4, 0.9> } finish { specular 0.4 } }
superellipsoid { <1, 0.1> rotate x * 90 scale <0.5, 0.8, 0.5> translate <-1.5, 0.8, -2.5>
  pigment { color rgb <0.9, 0.8, 0.2> } }
superellipsoid { <0.6, 3> scale <1, 0.3, 1> rotate <20, 30, 10> translate <1.8, 0.9, -2.6>
  pigment { color rgb <0.8, 0.4, 0.8> } }
superellipsoid { <4, 1.5> scale 0.6 rotate y * 45 translate <-3.6, 2.8, 2.5> pigment { color rgb <0.4, 0.9, 0.9> } }
