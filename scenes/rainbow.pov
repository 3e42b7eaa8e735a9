// Tests rainbow: two arcs (the second written first, both averaged where they overlap) with filtered colour maps
// over a sky and a ground plane (distance fades it over the plane), arc_angle and falloff_angle limiting the outer
// one, and an up vector that tilts it.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -10> look_at <0, 4, 0> angle 80 }
light_source { <-20, 30, -30> color rgb 1 }
background { color rgb <0.3, 0.45, 0.7> }
plane { y, 0 pigment { checker color rgb 0.6 color rgb 0.3 scale 2 } }
sphere { <3, 1, 4>, 1 pigment { rgb <0.9, 0.5, 0.2> } }
rainbow {
  angle 42.5 width 5 distance 40 direction <-0.2, -0.2, 1>
  colour_map {
    [0.000 colour rgbf <1.0, 0.5, 1.0, 1.0>]
    [0.100 colour rgbf <1.0, 0.5, 1.0, 0.8>]
    [0.300 colour rgbf <0.2, 0.2, 1.0, 0.8>]
    [0.500 colour rgbf <0.2, 1.0, 0.2, 0.8>]
    [0.700 colour rgbf <1.0, 1.0, 0.2, 0.8>]
    [0.900 colour rgbf <1.0, 0.2, 0.2, 0.8>]
    [1.000 colour rgbf <1.0, 0.2, 0.2, 1.0>]
  }
}
rainbow {
  angle 52 width 6 direction <-0.2, -0.2, 1> up <0.3, 1, 0> arc_angle 120 falloff_angle 60
  colour_map {
    [0.000 colour rgbt <1.0, 0.2, 0.2, 1.0>]
    [0.200 colour rgbt <1.0, 0.2, 0.2, 0.5>]
    [0.500 colour rgbt <0.2, 1.0, 0.2, 0.5>]
    [0.800 colour rgbt <0.2, 0.2, 1.0, 0.5>]
    [1.000 colour rgbt <0.2, 0.2, 1.0, 1.0>]
  }
}
