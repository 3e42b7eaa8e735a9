// Tests interior fade (pipeline §4 "interior fade", §3 shadows): coloured glass whose colour depends on the
// distance travelled inside, with fade_power 2, 1000 (exponential) and no fade_power (constant (1 + fc)/2).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -8> look_at <0, 0.8, 0> }
background { color rgb <0.9, 0.9, 0.9> }
light_source { <-3, 10, -6> color rgb 1 }
plane { y, 0 pigment { checker color rgb 1 color rgb 0.4 } }
box { <-3.5, 0, -0.6>, <-1.5, 1.6, 0.6> pigment { color rgbf <1, 1, 1, 1> }
      interior { ior 1.2 fade_distance 1 fade_power 2 fade_color <0.8, 0.3, 0.1> } }
sphere { <0.2, 1, 0>, 1 pigment { color rgbf <1, 1, 1, 1> }
         interior { ior 1.4 fade_distance 1.5 fade_power 1001 fade_colour <0.1, 0.5, 0.9> } }
sphere { <2.6, 0.8, 0>, 0.8 pigment { color rgbt <1, 1, 1, 1> } interior { fade_distance 1 fade_color <0.2, 0.9, 0.2> } }
