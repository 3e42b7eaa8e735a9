// Tests turbulence: the pattern keyword with octaves, omega and lambda, warp { turbulence } stacked with
// transforms, turbulence on a colour-mapped onion and on a pigment_map, and turbulent ground fog.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -8> look_at <0, 0.5, 0> angle 50 }
light_source { <-10, 10, -20> color rgb 1 }
background { color rgb <0.3, 0.4, 0.6> }
fog { fog_type 2 distance 6 fog_offset 0.2 fog_alt 0.6 color rgb <0.9, 0.9, 1> turbulence <0.5, 0.8, 0.5>
  octaves 5 omega 0.6 lambda 2.2 turb_depth 0.4 }
plane { y, -1 pigment { checker color rgb 0.9 color rgb 0.2 warp { turbulence 0.4 octaves 3 } scale 0.8 } }
sphere { <-2.2, 0.5, 0>, 1 pigment { onion turbulence <0.3, 0.6, 0.3> octaves 2 lambda 3
  color_map { [0 rgb <1, 0.4, 0.1>] [1 rgb <0.2, 0.1, 0.5>] } scale 0.3 } }
sphere { <0, 0.5, 0>, 1 pigment { gradient y turbulence 1.2 omega 0.3
  pigment_map { [0 rgb <0.1, 0.6, 0.2>] [0.5 granite scale 0.3] [1 rgb 1] } } }
sphere { <2.2, 0.5, 0>, 1 pigment { leopard warp { turbulence 0.6 } scale 0.1 warp { turbulence 0.3 lambda 1.5 }
  rotate z * 30 } }
