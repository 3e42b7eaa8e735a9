// Tests finish irid: thin-film interference on the light of each light source and on reflections, with the film
// thickness, turbulence (5 octaves of the scene's noise at the hit), diffuse_back on a thin sheet, a photon-free
// reflection, and irid_wavelength.
#version 3.7;
global_settings { assumed_gamma 1.0 irid_wavelength <0.3, 0.2, 0.12> }
camera { location <0, 3, -7> look_at <0, 0.8, 0> }
background { color rgb <0.3, 0.35, 0.5> }
light_source { <-4, 8, -6> color rgb <1, 1, 1> }
light_source { <5, 4, -3> color rgb <0.5, 0.4, 0.3> }
plane { y, 0 pigment { checker rgb 0.9, rgb 0.2 } }
sphere { <-2.2, 1, 0>, 0.9 pigment { rgb 0.6 } finish { diffuse 0.6 phong 0.8 irid { 0.4 thickness 0.5 } } }
sphere { <0, 1, 0>, 0.9 pigment { rgb 0.5 } finish { diffuse 0.5 specular 0.6 irid { 0.6 thickness 0.3 turbulence 0.8 } } }
sphere { <2.2, 1, 0>, 0.9 pigment { rgb 0.2 } finish { diffuse 0.3 reflection 0.6 irid { 0.5 thickness 1.2 } } }
box { <-1.5, 0, 1.5>, <1.5, 1.6, 1.52> pigment { rgb <0.9, 0.8, 0.6> } finish { diffuse 0.6, 0.4 irid { 0.3 thickness 0.7 turbulence <0.3, 5, 5> } } }
