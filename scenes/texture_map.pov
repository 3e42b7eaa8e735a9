// Tests texture_map: whole textures blended by a pattern (gradient, onion, radial with frequency and a wave), the
// entries of different finishes and transparency, an entry that is itself a patterned texture, a layered texture
// as an entry, an `average` of textures, a declared texture_map, and layer normals inside a turned and scaled
// pattern (taken through the pattern's transforms).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -10> look_at <0, 0.5, 0> angle 50 }
background { color rgb <0.2, 0.3, 0.4> }
light_source { <-6, 12, -8> color rgb <1, 1, 1> }
#declare Shiny = texture { pigment { color rgb <0.9, 0.2, 0.1> } finish { phong 0.9 phong_size 60 } }
#declare Mirror = texture { pigment { color rgb <0.1, 0.1, 0.1> } finish { reflection 0.6 } }
#declare Glow = texture { pigment { color rgb <0.2, 0.9, 0.3> } finish { ambient 0.8 diffuse 0.2 } }
#declare Clear = texture { pigment { color rgbt <0.3, 0.5, 1, 0.7> } }
#declare Layered = texture { pigment { color rgb <1, 1, 0.2> } } texture { pigment { gradient y color_map {
  [0 color rgbt <0, 0, 0, 1>] [1 color rgb <0.6, 0, 0.6>] } scale 0.3 } }
#declare Map = texture_map { [0.1 Shiny] [0.45 Glow] [0.55 Mirror] [0.9 Clear] }
plane { y, -1 texture { gradient x texture_map { [0 pigment { color rgb <0.9, 0.9, 0.85> }] [1 Mirror] } scale 3 } }
sphere { <-3, 0.5, 0>, 1.5 texture { gradient y texture_map { Map } scale 3 translate y * -1 } }
sphere { <0.5, 0.8, 1>, 1.5 texture { onion texture_map { [0.3 Glow] [0.3 checker texture { Shiny } texture { Mirror }
  scale 0.3] [0.7 Layered] } scale 0.6 } }
box { <-1, -1, -1>, <1, 1, 1> texture { radial frequency 4 triangle_wave texture_map { [0 Shiny] [1 Glow] } }
  rotate y * 30 translate <3.8, 0, 0> }
box { <-1, -0.1, -1>, <1, 0.1, 1> texture { average texture_map { [1 Shiny] [3 Glow] } } scale 0.8
  translate <-0.8, -0.6, -2.2> }
sphere { 0, 0.9 texture { gradient y texture_map {
    [0 pigment { color rgb <1, 0.6, 0.2> } normal { gradient x 0.6 scale 0.25 } finish { phong 0.8 }]
    [1 pigment { color rgb <0.3, 0.5, 1> } normal { onion 0.4 scale 0.3 } finish { phong 0.8 }] }
  scale <1, 2, 1> rotate z * 30 translate y * -0.9 } translate <2.2, -0.1, -3> }
