// Tests pattern normals sampled by slope (POV-Ray's four-point tetrahedron): gradient on a floor, onion on a
// sphere with an amount after the pattern, and a sine wave with frequency on a box.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -7> look_at <0, 0.6, 0> }
background { color rgb <0.1, 0.15, 0.25> }
light_source { <-4, 8, -6> color rgb <1, 1, 1> }
plane { y, 0 pigment { rgb <0.8, 0.7, 0.5> } normal { gradient x scale 0.7 } finish { phong 0.6 } }
sphere { <-1.2, 1, 0>, 1 pigment { rgb <0.3, 0.5, 0.9> } normal { onion 0.8 scale 0.3 } finish { specular 0.6 } }
box { <0.4, 0, -0.8>, <2.2, 1.6, 0.8> rotate y*-20 pigment { rgb <0.9, 0.4, 0.3> }
      normal { gradient y, 1.5 sine_wave frequency 3 } }
