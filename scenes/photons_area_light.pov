// Photons from every cell of an area light (light photons { area_light }): each cell shoots its own rings with the
// light's colour shared among the cells, and the spacing widened by the square root of the cell count.
#version 3.7;
global_settings { assumed_gamma 1 photons { spacing 0.01 } }
camera { location <0, 6, -4> look_at <0, -1, 0.5> angle 50 }
light_source { <-6, 8, 3> color rgb 1 area_light <2, 0, 0>, <0, 0, 2>, 3, 3
  photons { refraction on area_light } }
plane { y, -1 pigment { color rgb 0.8 } finish { ambient 0 } }
sphere { <0, 0.5, 0>, 1
  pigment { rgbf <0.8, 1, 0.9, 0.95> }
  finish { ambient 0 diffuse 0 }
  interior { ior 1.5 }
  photons { target refraction on }
}
