// Tests transformed media densities. Left: transforms in the media block (media { … scale, translate } after the
// density transform the density only) and in the density block (rotate). Middle: the same kind of media in a box
// that is scaled, rotated and translated after its interior (the object's transforms carry the density along:
// stripes stretched and tilted with the box). Right: a box translated before its interior is given (the density
// is not moved with it: its stripes stay where gradient x puts them in world space).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -7> look_at <0, 1.2, 0> }
background { color rgb <0.05, 0.05, 0.1> }
light_source { <-5, 10, -6> color rgb 0.8 }
plane { y, 0 pigment { checker color rgb 0.6 color rgb 0.1 } }
#declare Stripes = density { gradient x density_map { [0 color rgb 0] [0.5 color rgb 0] [0.5 color rgb 1] [1 color rgb 1] } }
box { <-3.2, 0, -1>, <-1.2, 2.4, 1> pigment { color rgbt <1, 1, 1, 1> } hollow
  interior { media {
    emission <0.9, 0.6, 0.2> absorption 0.3
    density { Stripes rotate z*30 }
    scale 0.6 translate <0.2, 0, 0>
  } } }
box { <-0.7, -1, -0.7>, <0.7, 1, 0.7> pigment { color rgbt <1, 1, 1, 1> } hollow
  interior { media {
    emission <0.2, 0.7, 0.9> absorption 0.3
    density { Stripes scale 0.5 }
  } }
  scale <1.2, 1.1, 0.9> rotate <0, -25, 20> translate <0.2, 1.3, 0> }
box { <-0.7, -1, -0.7>, <0.7, 1, 0.7> pigment { color rgbt <1, 1, 1, 1> } hollow
  translate <2.5, 1.1, 0.5>
  interior { media {
    emission <0.9, 0.3, 0.6> absorption 0.3
    density { Stripes scale 0.5 }
  } } }
