// Tests the mapping warps: planar (default and oriented with a distance), cylindrical (oriented, dist_exp), spherical,
// toroidal (major_radius) and cubic, each on a checker or gradient, with transforms before and after the warp.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -11> look_at <0, 0.5, 0> angle 44 right x * 4 / 3 }
light_source { <-8, 12, -10> color rgb 1 }
plane { y, -1 pigment { checker rgb 1 rgb 0.4 warp { planar y, 0.5 } scale 0.5 } }
sphere { <-3.3, 0.4, 1>, 1.1 pigment { checker rgb <1, 0.3, 0.2> rgb 1 scale <0.125, 0.25, 1> warp { spherical } } }
cylinder { <-1.1, -1, 1>, <-1.1, 1.6, 1>, 0.9
  pigment { checker rgb <0.2, 0.5, 1> rgb 1 scale <0.1, 0.3, 1> warp { cylindrical orientation <0, 1, 0.3> dist_exp 1 }
    translate <-1.1, 0, 1> } }
torus { 0.8, 0.35 rotate x * -60 translate <1.1, 0.4, 1>
  pigment { checker rgb <1, 0.8, 0.1> rgb 0.2 scale <0.0625, 0.125, 1> warp { toroidal major_radius 0.8 }
    rotate x * -60 translate <1.1, 0.4, 1> } }
box { <-0.9, -0.9, -0.9>, <0.9, 0.9, 0.9> rotate <20, 35, 0> translate <3.3, 0.3, 1>
  pigment { gradient x color_map { [0 rgb <0.1, 0.8, 0.3>] [0.5 rgb 1] [1 rgb <0.6, 0.1, 0.8>] } frequency 4
    warp { cubic } rotate <20, 35, 0> translate <3.3, 0.3, 1> } }
box { <-4, -1, -3.5>, <4, -0.9, -2.5>
  pigment { gradient x color_map { [0 rgb 0] [1 rgb 1] } warp { planar } scale 0.5 } }
