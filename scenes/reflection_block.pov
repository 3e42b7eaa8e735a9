// Tests the reflection { } block (pipeline §4): min/max with falloff, fresnel with an interior ior, metallic
// reflection tinted by the pigment, exponent, and conserve_energy on a transparent sphere.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -9> look_at <0, 1, 0> }
background { color rgb <0.5, 0.6, 0.8> }
light_source { <-6, 10, -8> color rgb 1 }
plane { y, 0 pigment { checker color rgb 1 color rgb <0.1, 0.3, 0.1> } }
sphere { <-3.3, 1, 0>, 1 pigment { color rgb <0.6, 0.1, 0.1> } finish { reflection { 0.1, 0.9 falloff 2 } } }
sphere { <-1.1, 1, 0>, 1 pigment { color rgb <0.1, 0.1, 0.6> } finish { reflection { 0, 1 fresnel on } }
         interior { ior 1.5 } }
sphere { <1.1, 1, 0>, 1 pigment { color rgb <1, 0.5, 0.25> } finish { reflection { 1 metallic } diffuse 0.2 } }
sphere { <3.3, 1, 0>, 1 pigment { color rgb <0.2, 0.2, 0.2> } finish { reflection { 0.5 exponent 2 } } }
sphere { <0, 0.5, -2.5>, 0.5 pigment { color rgbf <0.9, 0.9, 1, 0.7> }
         finish { reflection { 0.3 fresnel } conserve_energy } interior { ior 1.3 } }
