// Tests a pattern's own noise_generator (0: the scene's, 1 original, 2 range-corrected, 3 Perlin) against a scene
// generator of 3: in pigments, normals, a turbulence warp and a patterned texture.
#version 3.7;
global_settings { assumed_gamma 1.0 noise_generator 3 }
camera { location <0, 4, -7> look_at <0, 0.6, 0> }
background { color rgb <0.1, 0.15, 0.25> }
light_source { <-4, 8, -6> color rgb <1, 1, 1> }
#declare Map = color_map { [0 rgb <0, 0, 0.4>] [0.5 rgb <1, 0.8, 0.2>] [1 rgb <0.8, 0, 0>] }
plane { y, 0 pigment { bozo noise_generator 1 color_map { Map } scale 0.4 } }
sphere { <-2.4, 1, 0>, 0.9 pigment { granite noise_generator 0 color_map { Map } } finish { ambient 1 diffuse 0 } }
sphere { <-0.8, 1, 0>, 0.7 pigment { granite noise_generator 2 color_map { Map } } finish { ambient 1 diffuse 0 } }
sphere { <0.8, 1, 0>, 0.7 pigment { marble turbulence 1 noise_generator 1 color_map { Map } } finish { ambient 1 diffuse 0 } }
sphere { <2.4, 1, 0>, 0.9 pigment { rgb <1, 0.9, 0.7> } normal { wrinkles 1 noise_generator 2 scale 0.3 } }
box { <-1.5, 0, 1.5>, <1.5, 1.5, 1.7>
  texture { spotted noise_generator 1 scale 0.3
    texture_map { [0.4 pigment { rgb <0, 0.5, 0> } finish { ambient 1 diffuse 0 }] [0.6 pigment { rgb 1 } finish { ambient 1 diffuse 0 }] } } }
