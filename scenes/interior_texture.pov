// Tests interior_texture: the surface seen from inside takes the interior texture. Open cylinders and a clipped
// sphere show their inner walls (red/checker); a difference shows that the hole's wall, an inverted child, counts
// as outside (the exterior texture); a union passes its interior_texture to its children; a transparent exterior
// lets shadow rays through the inside's filter; an inverse sphere swaps which side is inside.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -9> look_at <0, 0.3, 0> angle 45 right x * 4 / 3 }
light_source { <-4, 8, -6> color rgb 1 }
light_source { <3, 2, -8> color rgb 0.4 }
plane { y, -1 pigment { checker rgb 0.8 rgb 0.5 scale 0.5 } }
cylinder { <-2.6, -1, 0>, <-2.6, 1, 0>, 0.8 open
  texture { pigment { rgb <0.2, 0.4, 1> } finish { phong 0.6 } }
  interior_texture { pigment { checker rgb <1, 0.2, 0.1> rgb 1 scale 0.25 } finish { diffuse 0.8 } }
  rotate x * -20 }
sphere { <0, 0.2, 0>, 1
  clipped_by { plane { -z, 0.1 } }
  pigment { rgb <0.1, 0.8, 0.3> }
  interior_texture { pigment { gradient y color_map { [0 rgb <1, 1, 0>] [1 rgb <1, 0, 0.5>] } } }
  rotate y * -30 }
difference {
  box { <-0.7, -1, -0.7>, <0.7, 0.4, 0.7> }
  cylinder { <0, -2, 0>, <0, 2, 0>, 0.4 }
  pigment { rgb <0.9, 0.6, 0.2> }
  interior_texture { pigment { rgb <0.2, 0.2, 0.2> } }
  rotate y * 20 translate <2.6, 0, 0.5> }
union {
  cylinder { <-1, 1.6, 1>, <1, 1.6, 1>, 0.35 open }
  cylinder { <-1, 1.6, 1>, <-1, 2.4, 1>, 0.25 open }
  pigment { rgb 0.9 }
  interior_texture { pigment { rgb <0.4, 0, 0.8> } finish { ambient 0.3 } }
  rotate y * 25 }
sphere { <1.6, -0.4, -2.2>, 0.6
  pigment { rgbf <1, 1, 1, 0.9> }
  interior_texture { pigment { rgbf <1, 0.3, 0.3, 0.6> } }
  inverse }
