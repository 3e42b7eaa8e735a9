// Tests media together with fog: a constant fog (distance 25) over the scene and a hollow box of emitting and
// absorbing media. The fog is applied to each ray segment outside objects (hollow ones included), after the media:
// the box's glow is fogged by the distance from the camera to the box, and the floor seen through the box gets the
// box's absorption and the fog of the whole path. A ground fog layer (fog_type 2) adds height dependence.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -7> look_at <0, 1, 2> }
background { color rgb <0.3, 0.4, 0.7> }
light_source { <-5, 10, -6> color rgb 1 }
fog { distance 25 color rgb <0.7, 0.7, 0.75> }
fog { fog_type 2 distance 6 color rgb <0.9, 0.8, 0.6> fog_offset 0.1 fog_alt 0.4 }
plane { y, 0 pigment { checker color rgb 0.9 color rgb 0.2 } }
sphere { <2.5, 1, 6>, 1 pigment { color rgb <0.9, 0.3, 0.2> } }
box { <-1.5, 0.01, -1>, <1, 2.3, 1> pigment { color rgbt <1, 1, 1, 1> } hollow rotate y*20 translate <-0.8, 0, 2>
  interior { media { emission <0.1, 0.3, 0.5> absorption <0.8, 0.5, 0.2> } } }
