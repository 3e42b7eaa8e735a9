// Tests a non-hollow object with media inside atmospheric media: a scene-level scattering media (lit by a point
// light) fills the space outside objects. Left: a transparent sphere that is not hollow, with emitting media: POV-Ray
// computes neither its media nor the atmosphere inside it (media only along hollow rays), so it shows as a clear
// hole in the haze. Middle: the same sphere but hollow: its media and the atmosphere both apply inside. Right: a
// transparent hollow box with no media of its own: the atmosphere goes on through it. A back wall (facing the camera,
// whose inside is behind it) catches every ray. No warning.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -7> look_at <0, 1.2, 0> }
light_source { <-3, 6, -4> color rgb <1, 0.9, 0.8> }
media { scattering { 1, <0.03, 0.03, 0.035> } }
plane { y, 0 pigment { checker color rgb 0.6 color rgb 0.1 } }
plane { -z, -2.5 pigment { color rgb <0.1, 0.1, 0.15> } }
sphere { <-2, 1.1, 0>, 1.1 pigment { color rgbt <1, 1, 1, 1> }
  interior { media { emission <0.05, 0.15, 0.4> } } }
sphere { <0.3, 1.1, 0.5>, 1.1 pigment { color rgbt <1, 1, 1, 1> } hollow
  interior { media { emission <0.05, 0.15, 0.4> } } }
box { <-0.9, 0.01, -0.8>, <0.9, 2.2, 0.8> pigment { color rgbt <1, 1, 1, 1> } hollow rotate y*-20 translate <2.6, 0, 0> }
