// Tests media given in a material { texture { … } interior { media { … } } }: the material's interior (and its
// transparent texture) go to the object as if given directly; the second object uses the material and then
// transforms the object, which carries the material's media density along (stripes of a gradient, tilted).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -7> look_at <0, 1.1, 0> }
background { color rgb <0.05, 0.05, 0.1> }
light_source { <-5, 10, -6> color rgb 0.8 }
plane { y, 0 pigment { checker color rgb 0.6 color rgb 0.1 } }
#declare Glow = material {
  texture { pigment { color rgbt <1, 1, 1, 1> } }
  interior { media { emission <0.8, 0.5, 0.2> absorption 0.4
                     density { gradient x density_map { [0 color rgb 0.2] [0.5 color rgb 0.2] [0.5 color rgb 1] [1 color rgb 1] } scale 0.6 } } }
}
sphere { <-1.4, 1.2, 0>, 1.2 material { Glow } hollow }
box { <-0.8, -1, -0.8>, <0.8, 1, 0.8> material { Glow } hollow rotate <0, 30, 25> translate <1.6, 1.3, 0> }
