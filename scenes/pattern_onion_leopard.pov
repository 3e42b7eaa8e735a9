// Tests onion (concentric spheres) on a floor, and leopard (squared mean of sines) on a sphere.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -7> look_at <0, 0.5, 0> }
background { color rgb <0.1, 0.15, 0.25> }
light_source { <-4, 8, -6> color rgb <1, 1, 1> }
plane { y, 0 pigment { onion scale 1.3 } finish { ambient 1 diffuse 0 } }
sphere { <0, 1, 0>, 1 pigment { leopard scale 0.15 color_map { [0 rgb <0.9, 0.8, 0.3>] [0.3 rgb <0.4, 0.2, 0.05>] [1 rgb 0] } } finish { ambient 1 diffuse 0 } }
