// Tests brick: the default grey mortar and red bricks on a wall, then brick_size, mortar and written colours.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -7> look_at <0, 0.5, 0> }
background { color rgb <0.1, 0.15, 0.25> }
light_source { <-4, 8, -6> color rgb <1, 1, 1> }
plane { z, 3 pigment { brick scale 0.1 } finish { ambient 1 diffuse 0 } }
plane { y, 0 pigment { brick color rgb <0.9, 0.9, 0.85>, color rgb <0.2, 0.3, 0.6> brick_size <1, 0.4, 0.6> mortar 0.08 } finish { ambient 1 diffuse 0 } }
sphere { <0, 1, 0>, 1 pigment { brick rgb 1, rgb <0.7, 0.2, 0.1> brick_size 0.5 mortar 0.05 } finish { ambient 0.3 diffuse 0.7 } }
