// Radiosity setting test (issue 19): no_radiosity on the sphere: radiosity rays pass through it (no shadow, no yellow bleeding).
// The room is room.inc; everything else is POV-Ray 3.7's default radiosity.
// counterpart: radiosity_default
#version 3.7;
global_settings {
  assumed_gamma 1.0
  radiosity {}
}
#declare Sphere_No_Radiosity = 1;
#include "room.inc"
