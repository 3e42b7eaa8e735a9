// Tests isosurfaces of POV-Ray's noise-based internal functions: a sphere roughened by f_noise3d, a block cut by
// f_ridged_mf and a slab of f_hetero_mf, and a pigment read through vturbulence at parse time.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "functions.inc"
camera { location <0, 2.5, -7> look_at <0, 0.2, 0> angle 50 }
light_source { <-6, 10, -8> color rgb 1 }
background { color rgb <0.2, 0.25, 0.35> }
#declare Shift = vturbulence(2, 0.5, 6, <0.3, 0.4, 0.5>);
isosurface { function { f_sphere(x, y, z, 1) - f_noise3d(x * 3, y * 3, z * 3) * 0.4 }
  contained_by { sphere { 0, 1.5 } } max_gradient 3
  pigment { rgb <1, 0.6, 0.3> + Shift * 0.2 } translate <-2.3, 0.3, 0> }
isosurface { function { y - f_ridged_mf(x, 0, z, 0.7, 2.1, 5, 1, 2, 2) * 0.3 }
  contained_by { box { <-1, -1, -1>, <1, 1, 1> } } max_gradient 6
  pigment { rgb <0.4, 0.8, 0.5> } translate <0, 0, 0.5> }
isosurface { function { z - f_hetero_mf(x * 2, y * 2, 0, 0.5, 2, 4, 0.3, 1, 2) * 0.3 }
  contained_by { box { <-1, -1, -0.5>, <1, 1, 1> } } max_gradient 4
  pigment { rgb <0.5, 0.6, 1> } rotate y * -30 translate <2.3, 0.2, 0> }
plane { y, -1.2 pigment { rgb 0.7 } }
