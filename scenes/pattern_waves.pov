// Tests the wave types ramp, triangle, sine, scallop, cubic and poly on stripes of a gradient.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -7> look_at <0, 0.5, 0> }
background { color rgb <0.1, 0.15, 0.25> }
light_source { <-4, 8, -6> color rgb <1, 1, 1> }
#declare Map = color_map { [0 rgb <0, 0, 0.1>] [1 rgb <1, 0.9, 0.5>] }
box { <-4, 0, -3.4>, <4, 0.01, -2.6> pigment { gradient x color_map { Map } ramp_wave scale 1.6 } finish { ambient 1 diffuse 0 } }
box { <-4, 0, -2.4>, <4, 0.01, -1.6> pigment { gradient x color_map { Map } triangle_wave scale 1.6 } finish { ambient 1 diffuse 0 } }
box { <-4, 0, -1.4>, <4, 0.01, -0.6> pigment { gradient x color_map { Map } sine_wave scale 1.6 } finish { ambient 1 diffuse 0 } }
box { <-4, 0, -0.4>, <4, 0.01, 0.4> pigment { gradient x color_map { Map } scallop_wave scale 1.6 } finish { ambient 1 diffuse 0 } }
box { <-4, 0, 0.6>, <4, 0.01, 1.4> pigment { gradient x color_map { Map } cubic_wave scale 1.6 } finish { ambient 1 diffuse 0 } }
box { <-4, 0, 1.6>, <4, 0.01, 2.4> pigment { gradient x color_map { Map } poly_wave 3 scale 1.6 } finish { ambient 1 diffuse 0 } }
box { <-4, 0, 2.6>, <4, 0.01, 3.4> pigment { gradient x color_map { Map } poly_wave scale 1.6 } finish { ambient 1 diffuse 0 } }
