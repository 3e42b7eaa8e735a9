// Tests cylindrical lights (parallel beams with radius, falloff and tightness around the axis, pipeline §3) and
// looks_like objects (moved with the light, casting no shadow).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 6, -9> look_at <0, 0.5, 0> }
background { color rgb 0.05 }
light_source { <0, 0, 0> color rgb <1, 0.9, 0.7> cylinder point_at <0, -1, 0> radius 1 falloff 2 tightness 2
               translate <-1.8, 6, 0.5> }
light_source { <2, 5, -1> color rgb <0.5, 0.7, 1> cylinder point_at <1.6, 0, 0.6> }
light_source { <0, 2.5, -2> color rgb 0.3
               looks_like { sphere { 0, 0.3 pigment { color rgb <1, 1, 0.6> } finish { ambient 1 diffuse 0 } } }
               translate x * 0.5 }
light_source { <-5, 8, -6> color rgb 0.15 }
plane { y, 0 pigment { color rgb 0.9 } }
sphere { <-1.8, 0.8, 0.5>, 0.8 pigment { color rgb <0.8, 0.3, 0.2> } }
box { <1, 0, 0>, <2.2, 1.2, 1.2> pigment { color rgb <0.3, 0.6, 0.9> } }
