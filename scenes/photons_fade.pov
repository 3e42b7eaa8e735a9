// Photons and fading: the light's fade_distance/fade_power taken at the distance each photon travelled, and the
// interior's fade (fade_distance, fade_power, fade_color) over the path inside the glass.
#version 3.7;
global_settings { assumed_gamma 1 photons { spacing 0.01 } }
camera { location <0, 6, -4> look_at <0, -1, 0.5> angle 50 }
light_source { <-6, 8, 3> color rgb 3 fade_distance 6 fade_power 2 photons { refraction on } }
plane { y, -1 pigment { color rgb 0.8 } finish { ambient 0 } }
sphere { <0, 0.5, 0>, 1
  pigment { rgbf <1, 1, 1, 0.98> }
  finish { ambient 0 diffuse 0 }
  interior { ior 1.5 fade_distance 0.8 fade_power 1001 fade_color <0.9, 0.5, 0.2> }
  photons { target refraction on }
}
