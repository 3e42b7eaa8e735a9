// Photons refracted by a glass sphere (global_settings { photons { spacing } }, object photons { target refraction },
// light photons { refraction }): the caustic focused on the floor, the light the sphere would have let through its
// shadow replaced by the photons (POV-Ray's ComputeShadowColour), the direction of each photon stored in two bytes
// and its colour in POV-Ray's RGBE, gathered with the radius POV-Ray estimates from the map's density.
#version 3.7;
global_settings { assumed_gamma 1 photons { spacing 0.01 } }
camera { location <0, 6, -4> look_at <0, -1, 0.5> angle 50 }
light_source { <-6, 8, 3> color rgb 1 photons { refraction on reflection on } }
plane { y, -1 pigment { color rgb 0.8 } finish { diffuse 0.8 ambient 0 } }
sphere { <0, 0.5, 0>, 1
  pigment { rgbf <1, 0.9, 0.7, 0.95> }
  finish { ambient 0 diffuse 0 phong 0.5 reflection 0.05 }
  interior { ior 1.5 }
  photons { target refraction on reflection on }
}
