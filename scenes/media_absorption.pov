// Tests absorption-only media (no emission, no scattering): a hollow box whose interior absorbs red and green more
// than blue, so the checker floor and the sphere behind it are seen darkened and tinted; rays crossing the box
// through more media (its corners vs its middle, the floor inside the box) are darker (Beer-Lambert, exp(-a d)).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -7> look_at <0, 1, 0> }
background { color rgb <0.6, 0.7, 0.9> }
light_source { <-5, 10, -6> color rgb 1 }
plane { y, 0 pigment { checker color rgb 0.9 color rgb 0.2 } }
sphere { <1.2, 1, 1.2>, 1 pigment { color rgb <1, 0.8, 0.3> } }
box { <-1.8, 0, -1>, <1.2, 2.2, 1> rotate y*25
      pigment { color rgbt <1, 1, 1, 1> } hollow
      interior { media { absorption <1.0, 0.7, 0.2> } } }
