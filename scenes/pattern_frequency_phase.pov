// Tests frequency and phase (including a negative frequency) on gradient and onion.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -7> look_at <0, 0.5, 0> }
background { color rgb <0.1, 0.15, 0.25> }
light_source { <-4, 8, -6> color rgb <1, 1, 1> }
#declare Map = color_map { [0 rgb <0.9, 0.1, 0.1>] [0.5 rgb <1, 1, 0.9>] [1 rgb <0.1, 0.1, 0.8>] }
box { <-4, 0, -3>, <4, 0.01, -1> pigment { gradient x color_map { Map } frequency 2.5 phase 0.3 } finish { ambient 1 diffuse 0 } }
box { <-4, 0, -0.8>, <4, 0.01, 1> pigment { gradient x color_map { Map } frequency -1.5 } finish { ambient 1 diffuse 0 } }
box { <-4, 0, 1.2>, <4, 0.01, 4> pigment { onion color_map { Map } frequency 0.5 phase 0.75 translate z*2.5 } finish { ambient 1 diffuse 0 } }
