// Tests atmospheric (scene-level) media: media { scattering { 1, 0.05 } } outside all objects, made visible by a
// spotlight's beam (only the stretch of each ray inside the cone is lit: media.cpp ComputeSpotLightInterval) with a
// sphere in the beam casting a shadow down through it; a dim point light that does not interact with media
// (media_interaction off) lights the floor. Rays that miss everything cross the atmosphere to POV-Ray's maximum
// distance before reaching the background.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -8> look_at <0, 1.5, 0> }
background { color rgb <0.1, 0.15, 0.3> }
light_source { <0.5, 7, 1> color rgb <1.5, 1.4, 1.1> spotlight point_at <-0.5, 0, 0> radius 14 falloff 20 tightness 2 }
light_source { <-6, 8, -8> color rgb 0.2 media_interaction off }
media { scattering { 1, 0.05 } }
plane { y, 0 pigment { checker color rgb 0.6 color rgb 0.15 } }
sphere { <0.1, 3.8, 0.6>, 0.6 pigment { color rgb <0.9, 0.3, 0.1> } }
box { <1.8, 0, -1>, <2.8, 1.5, 0> pigment { color rgb <0.2, 0.5, 0.9> } }
