// Tests a parallel light lighting scattering media: all light rays are parallel (to point_at − location), so the
// shadow volume of the small sphere through the box of scattering media is a straight cylinder (not a cone as from
// a point light), and the light is not dimmed by distance.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -7> look_at <0, 1.1, 0> }
background { color rgb <0.02, 0.02, 0.04> }
light_source { <-3, 6, -2> color rgb <1, 0.9, 0.8> parallel point_at <0, 0, 0> }
plane { y, 0 pigment { checker color rgb 0.4 color rgb 0.05 } }
sphere { <-0.8, 2, -0.3>, 0.5 pigment { color rgb <0.9, 0.2, 0.1> } }
box { <-2, 0.01, -1>, <2, 2.6, 1> pigment { color rgbt <1, 1, 1, 1> } hollow
  interior { media { scattering { 1, 0.25 } } } }
