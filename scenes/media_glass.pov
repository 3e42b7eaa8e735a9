// Tests media seen through a refracting glass sphere (ior 1.5) and in a mirror: a hollow sphere of emitting and
// absorbing media stands behind a glass sphere (refracted rays reach the media with their own interior lists) and
// is reflected in a mirror box behind, to the left (reflected rays cross the media too). The glass sphere itself is not
// hollow but has no media.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.2, -7> look_at <0, 1.2, 0> }
background { color rgb <0.2, 0.25, 0.35> }
light_source { <-5, 10, -6> color rgb 1 }
plane { y, 0 pigment { checker color rgb 0.8 color rgb 0.2 } }
sphere { <0.6, 1, -2.5>, 1 pigment { color rgbf <1, 1, 1, 0.95> } finish { phong 0.5 reflection 0.05 } interior { ior 1.5 } }
sphere { <1.2, 1.2, 0.5>, 1.2 pigment { color rgbt <1, 1, 1, 1> } hollow
  interior { media { emission <0.9, 0.5, 0.1> absorption <0.2, 0.5, 0.9>
                     density { gradient y scale 2.4 translate <0, 0, 0> density_map { [0 color rgb 1] [1 color rgb 0.2] } } } } }
box { <-4, 0, 0>, <4, 4, 0.2> rotate y*-30 translate <-1, 0, 3> pigment { color rgb 0.05 } finish { reflection 0.8 } }
