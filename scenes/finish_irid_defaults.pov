// Tests finish irid with POV-Ray 3.7's default irid_wavelength (0.70, 0.52, 0.48) on spheres of three film
// thicknesses, with specular highlights and turbulence, lit by a far light behind the camera.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -10> right x * 4 / 3 angle 23 look_at <0, 0, 0> }
light_source { <150, 150, -2500> color rgb 0.9 }
sphere { <-1, 0, 0>, 0.45 pigment { rgb 1 } finish { specular 1 roughness 0.001 diffuse 0.2 irid { 0.5 thickness 0.5 } } }
sphere { <0, 0, 0>, 0.45 pigment { rgb 1 } finish { diffuse 0.2 irid { 0.5 thickness 2 } } }
sphere { <1, 0, 0>, 0.45 pigment { rgb 1 } finish { diffuse 0.2 irid { 0.75 thickness 2 turbulence 0.5 } } }
