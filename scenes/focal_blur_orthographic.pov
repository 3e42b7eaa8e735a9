// Tests focal blur on an orthographic camera without focal_point: the plane in focus lies at the direction's
// length (set by the orthographic resize's look_at), and, as in POV-Ray 3.7 (JitterCameraRay), every blurred ray
// leaves from the camera location moved across the aperture, not from its own point on the image plane: the
// image is a blurred perspective-like view, reproduced.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0, 2, -6> look_at <0, 0.8, 0>
  aperture 0.3 blur_samples 12 }
light_source { <-4, 8, -5> color rgb 1 }
plane { y, 0 pigment { checker rgb 0.9 rgb 0.2 } }
sphere { <-1.5, 0.8, 2>, 0.8 pigment { rgb <0.8, 0.3, 0.2> } finish { phong 0.6 } }
sphere { <0, 0.8, 0>, 0.8 pigment { rgb <0.2, 0.7, 0.3> } finish { phong 0.6 } }
sphere { <1.2, 0.5, -2.5>, 0.5 pigment { rgb <0.2, 0.3, 0.9> } finish { phong 0.6 } }
