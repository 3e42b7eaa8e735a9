// Tests uv_mapping on the shapes of revolution POV-Ray gives their own uv: a lathe (u around y, v the segment and
// its parameter over the segment count) with a quadratic profile, and a closed sor, whose base and cap discs take
// v outside [0, 1] (base −1 … 0 from the axis out, cap 2 … 1), seen from below and above.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -10> look_at <0, 0.5, 0> angle 48 }
background { color rgb <0.2, 0.3, 0.4> }
light_source { <-5, 10, -10> color rgb <1, 1, 1> }
#declare Lit = finish { ambient 0.5 diffuse 0.6 }
#declare Checks = pigment { checker color rgb <0.95, 0.8, 0.2> color rgb <0.15, 0.3, 0.8> scale <0.0625, 0.125, 1> }
#declare Bands = pigment { gradient y color_map { [0 rgb <1, 0.2, 0.2>] [0.5 rgb <0.2, 1, 0.2>] [1 rgb <1, 0.2, 0.2>] }
  scale 0.5 }
lathe { quadratic_spline 6, <0.3, -1>, <1, -1>, <1.4, 0>, <0.6, 1>, <1, 2>, <0.8, 2.5>
  uv_mapping pigment { Checks } finish { Lit } rotate <-15, 30, 0> translate <-2.6, 0, 0> }
sor { 6, <0, -0.5>, <1.2, 0>, <0.6, 1>, <1, 2>, <0.5, 2.5>, <0.7, 3.2>
  uv_mapping pigment { Checks } finish { Lit } rotate <-30, 0, 0> translate <0.6, -0.6, 0> }
sor { 5, <0, 0>, <1, 0.2>, <0.8, 1>, <1.1, 1.8>, <0, 2>
  uv_mapping pigment { Bands } finish { Lit } rotate <160, 0, 20> translate <3.4, 1.4, 1> }
