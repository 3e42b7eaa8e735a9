// Tests the shadow of a transparent blob whose components' fields overlap: POV-Ray's blob reports only the crossings
// of the first stretch of its field that has any (Blob::All_Intersections stops there outside CSG), and its shadow
// walk looks again from each crossing, so the exit crossing counts too (povtrace collected one query's crossings and
// missed it: 44.8 dB before).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -6> look_at <0, 0.5, 0> angle 45 }
light_source { <-4, 8, -5> color rgb 1 }
plane { y, -1 pigment { checker rgb 0.9 rgb 0.3 } }
blob { threshold 0.6
  sphere { <-0.5, 0.5, 0>, 1, 1 } sphere { <0.5, 0.5, 0>, 1, 1 }
  pigment { rgb <0.1, 0.3, 1> filter 0.7 }
}
