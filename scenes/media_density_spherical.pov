// Tests a media density made of a spherical pattern with a density_map: the density is the map's colour at the
// pattern's value (1 at the centre, 0 at radius 1 and beyond), multiplying the media's emission and absorption per
// channel: the glowing sphere has a blue rim, a dark orange shell and a yellow-white core, and absorbs more where
// the map is high. The unit sphere's scale and translate come after its interior, so they carry the density along.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -7> look_at <0, 1, 0> }
background { color rgb <0.05, 0.05, 0.1> }
light_source { <-5, 10, -6> color rgb 0.8 }
plane { y, 0 pigment { checker color rgb 0.6 color rgb 0.1 } }
box { <0.3, 0, 2>, <2.5, 1.5, 3> pigment { color rgb <0.2, 0.8, 0.3> } }
sphere { 0, 1 pigment { color rgbt <1, 1, 1, 1> } hollow
  interior { media {
    emission 0.6
    absorption 0.6
    density { spherical
      density_map { [0 color rgb <0.1, 0.3, 1>] [0.3 color rgb <0.8, 0.3, 0>] [0.6 color rgb <0.2, 0.1, 0>]
                    [1 color rgb <1.5, 1.2, 0.6>] } }
  } }
  scale 1.4 translate <-0.2, 1.4, 0> }
