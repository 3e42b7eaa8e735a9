// Tests media in objects with a filtered or transmitting pigment on their surface: the light seen through the
// media is coloured by the surface where the ray enters and where it leaves (filter multiplies by the pigment's
// colour, transmit passes unchanged), and the surface also shows its own (diffuse) colour. Left: a sphere with a
// red-filtering surface around emitting and scattering media; right: a box with a partly transmitting blue surface
// around absorbing media.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -7> look_at <0, 1.1, 0> }
background { color rgb <0.1, 0.1, 0.15> }
light_source { <-4, 7, -5> color rgb 1 }
plane { y, 0 pigment { checker color rgb 0.8 color rgb 0.15 } }
sphere { <-1.3, 1.2, 0>, 1.2 pigment { color rgbf <1, 0.5, 0.4, 0.8> } hollow
  interior { media { emission <0.3, 0.4, 0.6> scattering { 1, 0.1 } } } }
box { <-0.9, 0.01, -0.9>, <0.9, 2, 0.9> rotate y*30 translate <1.6, 0, 0.3> pigment { color rgbt <0.3, 0.5, 1, 0.7> } hollow
  interior { media { absorption <0.2, 0.6, 1.0> } } }
