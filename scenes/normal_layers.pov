// Tests normals per layer, in declared textures and normals, #default { normal }, slope_map and reflection:
// each layer has its own normal, the reflection uses the reflecting layer's normal.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -7> look_at <0, 0.6, 0> }
background { color rgb <0.3, 0.4, 0.6> }
light_source { <-4, 8, -6> color rgb <1, 1, 1> }
#declare Wavy = normal { gradient z 0.7 scale 0.4 slope_map { [0 <0, 1>] [0.5 <1, 0>] [1 <0, -1>] } }
#declare Layered = texture { pigment { rgb <0.8, 0.3, 0.2> } normal { onion 0.5 scale 0.2 } }
                   texture { pigment { checker rgbt <1, 1, 1, 0.6> rgbt <0, 0, 0, 1> scale 0.5 }
                             normal { Wavy } finish { reflection 0.3 } }
plane { y, 0 pigment { rgb 0.6 } normal { Wavy rotate y*45 } finish { reflection 0.2 } }
sphere { <-1.2, 1, 0>, 1 texture { Layered } }
#default { normal { gradient x 0.6 triangle_wave scale 0.3 } }
sphere { <1.2, 1, 0>, 1 pigment { rgb <0.5, 0.9, 0.5> } finish { phong 0.7 } }
