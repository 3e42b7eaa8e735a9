// A pass_through object between the light and the target (object photons { pass_through }): photons cross it on
// their way to the glass without being stopped, filtered by its layers (POV-Ray 3.7 filters them before the
// target); objects that are neither target nor pass_through stop the photons that reach them first.
#version 3.7;
global_settings { assumed_gamma 1 photons { spacing 0.01 } }
camera { location <0, 6, -5> look_at <0, -0.5, 0.5> angle 50 }
light_source { <0, 9, 2> color rgb 1 photons { refraction on } }
plane { y, -1 pigment { color rgb 0.8 } finish { ambient 0 } }
box { <-3, 3, -1>, <0, 3.05, 5> pigment { color rgbf <0.4, 0.8, 1, 0.9> } photons { pass_through } }
box { <0, 3, -1>, <3, 3.05, 5> pigment { color rgbf <1, 0.6, 0.4, 0.9> } }
sphere { <0, 0.3, 0.8>, 1
  pigment { rgbf <1, 1, 1, 0.97> }
  finish { ambient 0 diffuse 0 }
  interior { ior 1.45 }
  photons { target refraction on }
}
