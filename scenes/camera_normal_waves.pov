// Tests a camera normal with a wave-source pattern (ripples use the scene's number_of_waves sources) through a
// fisheye camera: the pattern is read at the fisheye's own screen coordinates (polar angle, angle off the axis).
#version 3.7;
global_settings { assumed_gamma 1.0 number_of_waves 4 }
camera { fisheye location <0, 2, -4> look_at <0, 0.8, 0> angle 160 normal { ripples 0.4 frequency 3 } }
background { color rgb <0.1, 0.15, 0.25> }
light_source { <-4, 8, -6> color rgb <1, 1, 1> }
plane { y, 0 pigment { checker rgb 0.9, rgb 0.2 } }
sphere { <0, 1, 0>, 1 pigment { rgb <0.2, 0.6, 0.9> } finish { phong 0.6 } }
