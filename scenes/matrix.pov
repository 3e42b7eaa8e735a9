// Tests the matrix modifier: a sheared box and a sheared, scaled sphere (12-value matrix, row-vector convention).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -8> look_at <0, 1, 0> }
background { color rgb <0.1, 0.15, 0.25> }
light_source { <-4, 8, -6> color rgb <1, 1, 1> }
plane { y, 0 pigment { color rgb <0.8, 0.8, 0.7> } finish { ambient 0.1 diffuse 0.7 } }
// Shear x by y (x' = x + 0.6 y), then move left.
box { <-0.7, 0, -0.7>, <0.7, 2, 0.7>
  matrix < 1, 0, 0,
           0.6, 1, 0,
           0, 0, 1,
           -2.2, 0, 0 >
  pigment { color rgb <0.9, 0.3, 0.2> } finish { phong 0.5 } }
// Ellipsoid with shear z by x, and translation in the last row.
sphere { <0, 0, 0>, 1
  matrix < 1.2, 0, 0.5,
           0, 0.8, 0,
           0, 0, 1,
           1.8, 0.8, 0 >
  pigment { color rgb <0.3, 0.5, 0.9> } finish { phong 0.8 phong_size 30 } }
