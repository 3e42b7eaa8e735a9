// Tests patterned textures made of whole textures: checker, hexagon and brick with `texture { … }` entries of
// different finishes (phong, reflection, ambient) and transparency (shadows filtered through the chosen texture),
// the #default texture for an entry not written, and tiles { … tile2 … }.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -10> look_at <0, 0.5, 0> angle 50 }
background { color rgb <0.2, 0.3, 0.4> }
light_source { <-6, 12, -8> color rgb <1, 1, 1> }
light_source { <8, 6, -10> color rgb <0.3, 0.3, 0.35> }
#declare Shiny = texture { pigment { color rgb <0.9, 0.2, 0.1> } finish { phong 0.9 phong_size 60 } }
#declare Mirror = texture { pigment { color rgb <0.1, 0.1, 0.1> } finish { reflection 0.6 } }
#declare Glow = texture { pigment { color rgb <0.2, 0.9, 0.3> } finish { ambient 0.8 diffuse 0.2 } }
#declare Clear = texture { pigment { color rgbt <0.3, 0.5, 1, 0.7> } }
plane { y, -1 texture { checker texture { pigment { color rgb <0.9, 0.9, 0.85> } } texture { Mirror } scale 1.5 } }
sphere { <-3, 0.5, 0>, 1.5 texture { checker texture { Shiny } texture { Clear } scale 0.5 } }
sphere { <0.5, 0.8, 1>, 1.5 texture { hexagon texture { Shiny } texture { Glow } texture { Mirror } rotate x * 90 scale 0.4 } }
box { <-1, -1, -1>, <1, 1, 1> texture { brick texture { Glow } texture { Shiny } brick_size <0.5, 0.25, 0.5> mortar 0.05 }
  rotate y * 30 translate <3.8, 0, 0> }
box { <-1, -0.1, -1>, <1, 0.1, 1> texture { checker texture { Clear } } scale 0.8 translate <-0.8, -0.6, -2.2> }
box { <-1, -0.1, -1>, <1, 0.1, 1> texture { tiles { texture { Shiny } tile2 texture { Glow } } scale 0.5 }
  rotate x * -30 translate <2, -0.2, -3> }
