// Tests the blob: sphere components merging, a cylinder component with its rounded ends, a negative component
// carving a dent, a non-uniformly scaled component (an ellipsoid), a transformed blob, the old `component` syntax,
// and one solved with sturm.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -9> look_at <0, 1, 0> }
background { color rgb <0.1, 0.15, 0.25> }
light_source { <-4, 8, -5> color rgb <1, 1, 1> }
light_source { <6, 3, -3> color rgb <0.3, 0.3, 0.4> }
plane { y, 0 pigment { checker color rgb <0.8, 0.8, 0.7> color rgb <0.5, 0.5, 0.45> } }
blob { threshold 0.6
  sphere { <-0.5, 0, 0>, 1, 1 }
  sphere { <0.5, 0, 0>, 1, 1 }
  sphere { <0, 0.7, 0>, 0.8, strength 1 }
  translate <-3, 0.9, 0.5> pigment { color rgb <0.9, 0.3, 0.2> } finish { phong 0.5 } }
blob { threshold 0.5
  cylinder { <-1, 0, 0>, <1, 0.5, 0>, 0.6, 1.5 }
  sphere { <0.4, 0.3, -0.35>, 0.5, -1.5 }
  translate <0, 1.1, 0.5> pigment { color rgb <0.2, 0.8, 0.3> } finish { phong 0.5 } }
blob { threshold 0.4
  sphere { 0, 1, 1 scale <1.5, 0.6, 0.8> rotate z * 30 }
  sphere { <0.7, 0.5, 0>, 0.7, 1 }
  scale 0.9 rotate y * -25 translate <3, 0.8, 0.5> pigment { color rgb <0.3, 0.4, 0.9> } finish { specular 0.4 } }
blob { threshold 0.65
  component 1, 0.8, <-0.4, 0, 0>
  component 1, 0.8, <0.4, 0, 0>
  cylinder { <0, -0.5, 0>, <0, 0.6, 0>, 0.35, 1 }
  sturm
  translate <-1.5, 0.6, -2.3> pigment { color rgb <0.9, 0.8, 0.2> } }
blob { threshold 0.5
  sphere { 0, 0.9, 2 }
  sphere { <0.3, 0.3, -0.4>, 0.45, -3 }
  scale <1, 0.7, 1> translate <1.6, 0.6, -2.4> pigment { color rgb <0.8, 0.4, 0.8> } }
