// Tests the surface of revolution: a closed vase, an open one (no end discs), one solved with sturm and transformed
// non-uniformly, and a four-point one turned on its side.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -9> look_at <0, 1, 0> }
background { color rgb <0.1, 0.15, 0.25> }
light_source { <-4, 8, -5> color rgb <1, 1, 1> }
light_source { <6, 3, -3> color rgb <0.3, 0.3, 0.4> }
plane { y, 0 pigment { checker color rgb <0.8, 0.8, 0.7> color rgb <0.5, 0.5, 0.45> } }
sor { 7, <0, -0.5>, <0.6, 0>, <1, 0.5>, <0.5, 1>, <0.3, 1.5>, <0.8, 2>, <1, 2.5>
  translate <-3, 0, 0.5> pigment { color rgb <0.9, 0.3, 0.2> } finish { phong 0.5 } }
sor { 6, <0, -0.2>, <1, 0>, <0.8, 0.5>, <0.2, 1.2>, <0.6, 2>, <0.7, 2.5> open
  translate <0, 0, 0.5> pigment { color rgb <0.2, 0.8, 0.3> } finish { phong 0.5 } }
sor { 5, <1, -0.5>, <0.5, 0>, <1, 1>, <0.2, 2>, <0, 3> sturm
  scale <1, 0.7, 1.3> rotate z * 20 translate <3, 0.3, 0.5> pigment { color rgb <0.3, 0.4, 0.9> }
  finish { phong 0.5 } }
sor { 4, <0, 0>, <0.8, 0>, <0.8, 1>, <0, 1>
  rotate x * 90 translate <-1.5, 0.8, -2.3> pigment { color rgb <0.9, 0.8, 0.2> } }
