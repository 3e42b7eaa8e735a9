// Tests the second diffuse value (backside diffuse): surfaces lit from behind glow; without it they stay dark.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> look_at <0, 0.5, 0> }
background { color rgb <0.05, 0.05, 0.1> }
// This light is below the floor: the floor's upper side only receives backside diffuse.
light_source { <1, -3, -2> color rgb <1, 0.9, 0.8> }
// This light is inside the left sphere: its outer surface is lit from behind.
light_source { <-2, 1.2, 0> color rgb <0.6, 0.8, 1> }
plane { y, 0 pigment { color rgb <0.8, 0.8, 0.8> } finish { ambient 0.05 diffuse 0.6, 0.5 } }
sphere { <-2, 1.2, 0>, 1 pigment { color rgb <1, 0.8, 0.4> } finish { ambient 0.05 diffuse 0.6, 0.8 } }
// Same light set-up but no backside value: stays at ambient.
sphere { <2, 1.2, 0>, 1 pigment { color rgb <1, 0.8, 0.4> } finish { ambient 0.05 diffuse 0.6 } }
