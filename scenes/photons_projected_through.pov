// Tests the light item projected_through { object }: photons from the light are shot only where they pass through
// the object (here a slab cutting the glass sphere's upper half, as seen from the light), starting beyond its last
// crossing; POV-Ray 3.7 uses it for photons only, so direct light and shadows are the same as without it. The
// caustic under the sphere is cut by the slab's projection.
#version 3.7;
global_settings { assumed_gamma 1 photons { spacing 0.01 } }
camera { location <0, 6, -4> look_at <0, -1, 0.5> angle 50 }
light_source { <-6, 8, 3> color rgb 1 photons { refraction on reflection on }
  projected_through { box { <-4, 5, 1.2>, <0, 5.3, 4> } } }
plane { y, -1 pigment { color rgb 0.8 } finish { diffuse 0.8 ambient 0 } }
sphere { <0, 0.5, 0>, 1
  pigment { rgbf <1, 0.9, 0.7, 0.95> }
  finish { ambient 0 diffuse 0 phong 0.5 reflection 0.05 }
  interior { ior 1.5 }
  photons { target refraction on reflection on }
}
