// Tests emission-only media: a hollow sphere whose interior glows orange (emission adds light along the ray, more
// where the ray crosses more media: brightest through the centre, fading to the rim); no absorption, so the floor
// and the box behind it still show through unattenuated, and the emission lights nothing else (no light source
// needed for it; the scene's light only lights the floor and the box).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -7> look_at <0, 1, 0> }
background { color rgb <0.05, 0.05, 0.1> }
light_source { <-5, 10, -6> color rgb 0.8 }
plane { y, 0 pigment { checker color rgb 0.6 color rgb 0.1 } }
box { <0.3, 0, 2>, <2.5, 1.5, 3> pigment { color rgb <0.2, 0.4, 0.9> } }
sphere { <-0.3, 1.3, 0>, 1.3 pigment { color rgbt <1, 1, 1, 1> } hollow
         interior { media { emission <0.5, 0.25, 0.05> } } }
