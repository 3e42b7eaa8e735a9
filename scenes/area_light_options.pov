// Tests area_light options (pipeline §3): adaptive 1 on a 9×9 light (subdivides only where corner samples differ by
// more than 0.1), circular with orient, and an area light that is also a spotlight.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -8> look_at <0, 0.5, 0> }
background { color rgb 0.1 }
light_source { <-3, 7, -1> color rgb 0.7 area_light <4, 0, 0>, <0, 0, 4>, 9, 9 adaptive 1 }
light_source { <3, 5, -4> color rgb 0.5 area_light <2, 0, 0>, <0, 2, 0>, 6, 6 circular orient }
light_source { <0, 8, 0> color rgb 0.4 spotlight point_at <1, 0, 0> radius 20 falloff 30
               area_light <1, 0, 0>, <0, 0, 1>, 3, 3 }
plane { y, 0 pigment { color rgb 0.9 } }
sphere { <-1.5, 1, 0.5>, 1 pigment { color rgb <0.9, 0.8, 0.2> } }
box { <1, 0, -0.5>, <2, 2, 0.5> pigment { color rgb <0.3, 0.8, 0.4> } }
