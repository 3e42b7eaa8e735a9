// Tests double_illuminate: a thin disc and a triangle lit from behind show their lit side on the side the
// camera sees; set on a union it reaches the children, `double_illuminate off` on a copy clears it, and highlights
// and brilliance take |N.L|.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -8> look_at <0, 0.5, 0> angle 45 right x * 4 / 3 }
light_source { <0, 3, 10> color rgb 1 }
light_source { <-6, 6, -6> color rgb 0.12 }
plane { y, -1 pigment { rgb 0.7 } }
disc { <-2.4, 0.6, 0>, z, 1 pigment { rgb <1, 0.6, 0.2> } finish { phong 0.8 phong_size 20 brilliance 2 }
  double_illuminate }
#declare Leaves = union {
  disc { <0, 0.2, 0>, <0.3, 0, -1>, 0.7 }
  triangle { <-0.6, 0.9, 0.2>, <0.6, 0.9, 0.2>, <0, 1.9, 0.4> }
  pigment { rgb <0.3, 0.6, 1> } finish { specular 0.6 roughness 0.02 metallic 0.5 }
  double_illuminate }
object { Leaves }
object { Leaves double_illuminate off translate x * 2.4 }
