// collect off (object photons { collect off }): photons are not stored on that object, its surfaces get none of
// their light, and a target between it and the light shadows it as without photons (the left half of the floor);
// the right half collects them.
#version 3.7;
global_settings { assumed_gamma 1 photons { spacing 0.01 } }
camera { location <0, 6, -5> look_at <0, -0.8, 0.6> angle 55 }
light_source { <0, 9, 3> color rgb 1 photons { refraction on } }
box { <-4, -2, -4>, <0, -1, 6> pigment { color rgb 0.8 } finish { ambient 0 } photons { collect off } }
box { <0, -2, -4>, <4, -1, 6> pigment { color rgb 0.8 } finish { ambient 0 } }
sphere { <0, 0.3, 0.8>, 1.2
  pigment { rgbf <1, 1, 1, 0.95> }
  finish { ambient 0 diffuse 0 }
  interior { ior 1.5 }
  photons { target refraction on }
}
