// Tests warp black_hole: plain, inverse, with falloff and strength, and repeated with turbulence (the centre
// jittered per cell from POV-Ray's random table, and moved up to the radius with the repeat vector grown).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -10> look_at 0 angle 50 right x * 4 / 3 }
light_source { <-5, 5, -20> color rgb 1 }
#declare Grid = pigment { checker rgb 1 rgb <0.2, 0.3, 0.8> scale 0.25 }
box { <-6, 0.2, 0>, <-0.2, 4, 1> pigment { Grid warp { black_hole <-3, 2, 0>, 1.5 } } }
box { <0.2, 0.2, 0>, <6, 4, 1> pigment { Grid warp { black_hole <3, 2, 0>, 1.5 falloff 4 strength 2 inverse } } }
box { <-6, -4, 0>, <6, -0.2, 1>
  pigment { Grid warp { black_hole <0, 0, 0>, 0.6 falloff 3 strength 0.75 repeat <1.5, 1.4, 0> turbulence <0.3, 0.2, 0> }
    warp { black_hole <0, 0, 0>, 1.2 inverse } translate <0, -2, 0> } }
