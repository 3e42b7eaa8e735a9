// The gather settings: gather min, max; radius (given, with its multiplier); expand_thresholds; jitter and autostop
// (rings past half the target's cone after one that missed it end the shooting).
#version 3.7;
global_settings { assumed_gamma 1
  photons { spacing 0.012 gather 10, 40 radius 0.08, 1.5 expand_thresholds 0.3, 15 jitter 0.6 autostop 0.5 } }
camera { location <0, 6, -4> look_at <0, -1, 0.5> angle 50 }
light_source { <-6, 8, 3> color rgb 1 photons { refraction on } }
plane { y, -1 pigment { color rgb 0.8 } finish { ambient 0 } }
sphere { <0, 0.5, 0>, 1
  pigment { rgbf <1, 0.9, 0.7, 0.95> }
  finish { ambient 0 diffuse 0 }
  interior { ior 1.5 }
  photons { target refraction on }
}
