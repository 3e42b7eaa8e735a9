// Tests a media density made of a gradient pattern with a color_map (a synonym of density_map in a density): the
// box glows red at the bottom, green in the middle, blue at the top (gradient y, scaled to the box's height), with
// a gap of zero density (fully clear) in between; the map's values repeat beyond the box (not seen).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -7> look_at <0, 1.2, 0> }
background { color rgb <0.05, 0.05, 0.1> }
light_source { <-5, 10, -6> color rgb 0.8 }
plane { y, 0 pigment { checker color rgb 0.6 color rgb 0.1 } }
sphere { <1.4, 0.7, 2.5>, 0.7 pigment { color rgb <0.9, 0.8, 0.2> } }
box { <-1.6, 0, -1>, <1.6, 2.6, 1> pigment { color rgbt <1, 1, 1, 1> } hollow rotate y*-20
  interior { media {
    emission 0.5
    absorption 0.3
    density { gradient y scale 2.6
      color_map { [0 color rgb <1, 0, 0>] [0.3 color rgb <1, 0.2, 0>] [0.4 color rgb 0] [0.5 color rgb <0, 1, 0>]
                  [0.7 color rgb <0, 0.6, 0.2>] [0.8 color rgb 0] [0.85 color rgb <0, 0, 1.5>] [1 color rgb <0.5, 0.5, 1.5>] } }
  } } }
