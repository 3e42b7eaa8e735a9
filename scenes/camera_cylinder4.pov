// Tests the cylinder 4 camera projection (cylinder 4 angle 120): POV-Ray's CreateCameraRay, with objects
// ahead, to the sides and behind the camera.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { cylinder 4 angle 120 location <0, 2, -6> look_at <0, 1, 0> }
background { color rgb <0.1, 0.15, 0.25> }
light_source { <-4, 8, -6> color rgb 1 }
plane { y, 0 pigment { checker rgb 0.9 rgb 0.4 } }
sphere { <-2, 1, 0>, 1 pigment { rgb <0.9, 0.3, 0.2> } }
box { <0.5, 0, -0.5>, <1.5, 2, 0.5> pigment { rgb <0.3, 0.8, 0.3> } }
sphere { <0, 1, 3>, 1 pigment { rgb <0.3, 0.4, 0.9> } }
sphere { <0, 1, -9>, 1 pigment { rgb <0.9, 0.9, 0.3> } }
