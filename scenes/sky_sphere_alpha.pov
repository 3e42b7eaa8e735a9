// Tests sky_sphere and background transparency with alpha output (pipeline §5): a partly transparent sky over an
// rgbt background; camera rays show the transparency, the mirror's reflected rays see the sky opaque.
// switches: +UA
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -6> look_at <0, 1.5, 0> angle 80 }
background { rgbt <0.2, 0.4, 0.6, 0.5> }
sky_sphere { pigment { gradient y color_map { [0 color rgbt <1, 0.5, 0.2, 0.3>] [1 color rgbft <0.1, 0.2, 0.9, 0.4, 0.2>] } } }
light_source { <-5, 10, -5> color rgb 1 }
sphere { <0, 1.2, 0>, 1.2 pigment { color rgb 0.1 } finish { reflection 0.8 } }
