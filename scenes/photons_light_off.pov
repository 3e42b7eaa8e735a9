// The light's photons { refraction off } wins over the target's `on`: that light shoots no photons at it, and the
// glass shadows its light as without photons (filtered by the glass). The other light's photons replace its light
// through the glass.
#version 3.7;
global_settings { assumed_gamma 1 photons { spacing 0.01 } }
camera { location <0, 6, -4> look_at <0, -1, 0.5> angle 50 }
light_source { <-6, 8, 3> color rgb 0.6 photons { refraction on } }
light_source { <6, 8, 3> color rgb 0.6 photons { refraction off } }
plane { y, -1 pigment { color rgb 0.8 } finish { ambient 0 } }
sphere { <0, 0.5, 0>, 1
  pigment { rgbf <1, 0.9, 0.7, 0.9> }
  finish { ambient 0 diffuse 0 }
  interior { ior 1.5 }
  photons { target refraction on }
}
