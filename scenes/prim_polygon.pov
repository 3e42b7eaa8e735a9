// Tests polygon: a star (concave), a square with a square hole (two sub-polygons, even-odd fill), one left
// unclosed (POV-Ray closes it with a warning), and a transformed polygon.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> look_at <0, 1, 0> }
background { color rgb <0.1, 0.15, 0.25> }
light_source { <-4, 8, -5> color rgb <1, 1, 1> }
light_source { <6, 3, -3> color rgb <0.3, 0.3, 0.4> }
plane { y, 0 pigment { checker color rgb <0.8, 0.8, 0.7> color rgb <0.4, 0.4, 0.35> } finish { ambient 0.1 diffuse 0.7 } }
polygon { 11,
  <0, 1>, <0.22, 0.31>, <0.95, 0.31>, <0.36, -0.12>, <0.59, -0.81>, <0, -0.38>, <-0.59, -0.81>, <-0.36, -0.12>,
  <-0.95, 0.31>, <-0.22, 0.31>, <0, 1>
  translate <-2.4, 1.3, 0> pigment { color rgb <0.9, 0.7, 0.2> } finish { phong 0.4 }
}
polygon { 10,
  <-1, 0, 0>, <1, 0, 0>, <1, 2, 0>, <-1, 2, 0>, <-1, 0, 0>,
  <-0.5, 0.5, 0>, <0.5, 0.5, 0>, <0.5, 1.5, 0>, <-0.5, 1.5, 0>, <-0.5, 0.5, 0>
  rotate y*20 translate <0, 0, 0.8> pigment { color rgb <0.2, 0.8, 0.3> }
}
// Not closed: the closing point is added.
polygon { 4, <0, 0, 0>, <1.4, 0, 0>, <1.6, 1.6, 0>, <0.2, 1.8, 0>
  rotate <0, -40, 10> translate <1.8, 0.1, 0> pigment { color rgb <0.3, 0.4, 0.9> } finish { specular 0.5 }
}
