// Tests height fields in CSG: a height field clipped by a cylinder (its walk over the cells goes on past hits the
// clip removes), a cylinder clipped by the same height field (the height field's inside goes on below its
// bottom, so the cylinder's wall stays there), and the intersection of a height field with a box and the
// difference of a box and a height field (every crossing of a CSG child counts).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 7, -9> look_at <0, 0.3, 0> angle 48 }
background { color rgb <0.1, 0.15, 0.25> }
light_source { <-4, 9, -6> color rgb <1, 1, 1> }
light_source { <6, 4, -4> color rgb <0.35, 0.35, 0.4> }
plane { y, -1.5 pigment { checker color rgb <0.8, 0.8, 0.7> color rgb <0.5, 0.5, 0.45> } }
#declare Terrain = height_field { png "height_field_terrain.png" smooth translate <-0.5, 0, -0.5> scale <3, 1.2, 3> }
object { Terrain clipped_by { cylinder { -2*y, 2*y, 1.3 } } translate <-3, 0, 1>
  pigment { color rgb <0.9, 0.5, 0.3> } finish { phong 0.3 } }
cylinder { -1.4*y, 1.4*y, 1.2 clipped_by { object { Terrain } } translate <0, 0, 1>
  pigment { color rgb <0.4, 0.7, 0.9> } finish { phong 0.3 } }
intersection { object { Terrain } box { <-1, -0.5, -1>, <1, 0.6, 1> } translate <3, 0, 1>
  pigment { color rgb <0.4, 0.85, 0.4> } }
difference { box { <-1.05, -0.3, -0.8>, <1.05, 0.5, 0.8> } object { Terrain scale <0.8, 0.8, 0.5> }
  translate <0, 0, -2.6> pigment { color rgb <0.85, 0.8, 0.45> } }
