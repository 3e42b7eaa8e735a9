// Tests two density blocks in one media: the media's density is their product (POV-Ray multiplies the density
// colours), here vertical stripes (gradient x with a density_map) times a spherical fall-off, so the glowing sphere
// shows stripes that fade towards its rim; the second density is coloured, so the product is coloured too.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -7> look_at <0, 1, 0> }
background { color rgb <0.05, 0.05, 0.1> }
light_source { <-5, 10, -6> color rgb 0.8 }
plane { y, 0 pigment { checker color rgb 0.6 color rgb 0.1 } }
box { <0.3, 0, 2>, <2.5, 1.5, 3> pigment { color rgb <0.2, 0.4, 0.9> } }
sphere { <-0.2, 1.4, 0>, 1.4 pigment { color rgbt <1, 1, 1, 1> } hollow
  interior { media {
    emission 0.9
    absorption 0.4
    density { gradient x scale 0.7 density_map { [0 color rgb 0] [0.5 color rgb 0] [0.5 color rgb 1] [1 color rgb 1] } }
    density { spherical scale 1.4 translate <-0.2, 1.4, 0>
              density_map { [0 color rgb 0] [1 color rgb <1, 0.6, 0.2>] } }
  } } }
