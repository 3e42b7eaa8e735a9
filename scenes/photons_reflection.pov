// Photons reflected by a metal ring (object photons { target reflection on refraction off }): the cardioid caustic
// inside the ring, from each layer's reflectivity (reflection with metallic) and the object's flags; the light's
// photons block is left out, so the object's `on` decides.
#version 3.7;
global_settings { assumed_gamma 1 photons { spacing 0.005 } }
camera { location <0, 5, -3> look_at <0, 0, 0> angle 45 }
light_source { <0, 3, -6> color rgb 1.2 }
plane { y, 0 pigment { color rgb 0.7 } finish { ambient 0 } }
difference {
  cylinder { <0, 0, 0>, <0, 0.6, 0>, 1.5 }
  cylinder { <0, -0.1, 0>, <0, 0.7, 0>, 1.4 }
  pigment { color rgb <0.9, 0.8, 0.5> }
  finish { ambient 0 diffuse 0.1 reflection { 0.9 metallic } specular 0.5 roughness 0.01 }
  photons { target reflection on refraction off }
}
