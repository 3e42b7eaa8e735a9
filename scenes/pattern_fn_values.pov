// Tests pattern functions (function { pattern { … } }) evaluated while rendering: a pigment function pattern that calls
// one, and an isosurface displaced by one.
#version 3.7;
#declare F = function { pattern { marble turbulence 0.6 scale 0.7 } }
#declare B = function { pattern { bumps scale 0.3 } }
camera { location <0, 2, -5> look_at 0 }
light_source { <-5, 10, -10>, rgb 1 }
plane { y, -1 pigment { function { F(x, y, z) } color_map { [0 rgb <1,0.5,0>] [1 rgb <0,0.3,1>] } } }
isosurface { function { sqrt(x*x+y*y+z*z) - 1 + B(x, y, z)*0.3 } contained_by { sphere { 0, 1.5 } } max_gradient 3
  pigment { rgb 1 } }
