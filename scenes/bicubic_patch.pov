// Tests bicubic_patch: type 1 with flatness and steps, type 0 (the same pieces), the default steps (two triangles),
// uv_vectors with uv_mapping, a patch with a collapsed edge (the <1, 0, 0> normal fallback), transforms moving the
// control points, and the old positional syntax.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 6, -10> look_at <0, 0.3, 0> angle 44 right x * 4 / 3 }
light_source { <-10, 20, -15> color rgb 1 }
light_source { <10, 5, -10> color rgb 0.4 }
background { rgb <0.3, 0.3, 0.4> }
#macro Net() <0, 0, 2>, <1, 0, 3>, <2, 0, 0>, <3, 0, 0>,
  <0, 1, 0>, <1, 1, 0>, <2, 1, 0>, <3, 1, -2>,
  <0, 2, 0>, <1, 2, 5>, <2, 2, 0>, <3, 2, 0>,
  <0, 3, 0>, <1, 3, 0>, <2, 3, -2>, <3, 3, 1> #end
bicubic_patch { type 1 flatness 0.1 u_steps 4 v_steps 3 Net()
  pigment { checker rgb <1, 0.4, 0.2> rgb 1 scale 0.5 } finish { phong 0.6 }
  translate <-1.5, -1.5, 0> scale 0.8 rotate <80, 20, 0> translate <-3.2, 0.5, 1> }
bicubic_patch { type 0 flatness 0.1 u_steps 4 v_steps 3 Net()
  pigment { checker rgb <0.2, 0.6, 1> rgb 1 scale 0.5 } finish { phong 0.6 }
  translate <-1.5, -1.5, 0> scale 0.8 rotate <80, 20, 0> translate <0, 0.5, 1> }
bicubic_patch { type 1 Net()
  pigment { rgb <0.6, 1, 0.5> }
  translate <-1.5, -1.5, 0> scale 0.8 rotate <80, 20, 0> translate <3.2, 0.5, 1> }
bicubic_patch { type 1 flatness 0.01 u_steps 3 v_steps 3 uv_vectors <0, 0> <1, 0> <1, 1> <0, 1>
  <1, 0, 0>, <1, 0, 0>, <1, 0, 0>, <1, 0, 0>,
  <0.6, 1, 0>, <1, 1, 1>, <1.4, 1, 0>, <1, 1, -1>,
  <0, 2, 0>, <1, 2, 2>, <2, 2, 0>, <1, 2, -2>,
  <0, 3, 0>, <1, 3, 1>, <2, 3, 0>, <1, 3, -1>
  uv_mapping pigment { checker rgb <1, 1, 0.3> rgb <0.3, 0.3, 1> scale 0.25 }
  rotate x * 90 translate <-2.5, -1.2, -2.5> }
bicubic_patch { 1 5 5
  <0, 0, 0>, <1, 0, 1>, <2, 0, 1>, <3, 0, 0>,
  <0, 1, 1>, <1, 1, 2>, <2, 1, 2>, <3, 1, 1>,
  <0, 2, 1>, <1, 2, 2>, <2, 2, 2>, <3, 2, 1>,
  <0, 3, 0>, <1, 3, 1>, <2, 3, 1>, <3, 3, 0>
  pigment { rgb <1, 0.7, 0.9> } finish { specular 0.5 }
  translate <-1.5, -1.5, 0> scale 0.7 rotate x * 90 translate <2.5, -1.2, -2.5> }
