// Tests a declared media (#declare M = media { … }) used twice with different transforms: media { M } as is in
// the left box, and media { M scale … rotate … translate … } in the right one, whose transforms apply to the copy's
// density only (the declared media is not changed: the left box is like using M alone). The declared media has
// default sampling (method 3), emission, absorption and a spherical density.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -7> look_at <0, 1.1, 0> }
background { color rgb <0.05, 0.05, 0.1> }
light_source { <-5, 10, -6> color rgb 0.8 }
plane { y, 0 pigment { checker color rgb 0.6 color rgb 0.1 } }
#declare M = media {
  emission <1.8, 1.2, 0.6> absorption <0.3, 0.5, 0.8>
  density { spherical density_map { [0 color rgb 0] [0.4 color rgb <0.2, 0.5, 1>] [1 color rgb 1.5] } }
}
box { <-1, -1, -1>, <1, 1, 1> pigment { color rgbt <1, 1, 1, 1> } hollow
  interior { media { M } } translate <-1.7, 1.2, 0> }
box { <-1, -1, -1>, <1, 1, 1> pigment { color rgbt <1, 1, 1, 1> } hollow
  interior { media { M scale <0.5, 1.5, 1> rotate z*-30 translate <0.3, 0, 0> } } translate <1.5, 1.2, 0> }
