// Tests transform order: rotate then translate (left box) versus translate then rotate (right box), plus scale then translate.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 6, -9> look_at <0, 0.5, 0.5> }
background { color rgb <0.1, 0.15, 0.25> }
light_source { <-4, 8, -6> color rgb <1, 1, 1> }
plane { y, 0 pigment { color rgb <0.8, 0.8, 0.7> } finish { ambient 0.1 diffuse 0.7 } }
box { <-0.5, 0, -0.5>, <0.5, 1, 0.5> rotate y*30 translate <-2.5, 0, 0> pigment { color rgb <0.9, 0.3, 0.2> } }
box { <-0.5, 0, -0.5>, <0.5, 1, 0.5> translate <2.5, 0, 0> rotate y*30 pigment { color rgb <0.2, 0.8, 0.3> } }
box { <-0.5, 0, -0.5>, <0.5, 1, 0.5> scale <1, 0.5, 2> rotate <0, -20, 0> translate <0, 0, 2> pigment { color rgb <0.3, 0.4, 0.9> } }
sphere { <0, 0, 0>, 0.5 translate <0, 0.5, 0> rotate z*-40 pigment { color rgb <0.9, 0.8, 0.3> } finish { phong 0.6 } }
