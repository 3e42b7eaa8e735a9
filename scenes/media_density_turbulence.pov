// Tests a media density with turbulence: a spherical density whose pattern is warped by turbulence 0.6 (octaves 4,
// omega 0.5, lambda 2.5), making ragged glowing clouds with an absorbing component, over a checker floor.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -7> look_at <0, 1, 0> }
background { color rgb <0.3, 0.4, 0.6> }
light_source { <-5, 10, -6> color rgb 0.8 }
plane { y, 0 pigment { checker color rgb 0.8 color rgb 0.2 } }
sphere { <-0.2, 1.4, 0>, 1.4 pigment { color rgbt <1, 1, 1, 1> } hollow
  interior { media {
    emission <0.8, 0.5, 0.3>
    absorption <0.5, 0.7, 0.9>
    density { spherical turbulence 0.6 octaves 4 omega 0.5 lambda 2.5 scale 1.4 translate <-0.2, 1.4, 0>
              density_map { [0 color rgb 0] [0.3 color rgb 0] [0.5 color rgb 1] [1 color rgb 2] } }
  } } }
