// Radiosity setting test (issue 19): count 400 (default 35): many more rays per sample.
// The room is room.inc; everything else is POV-Ray 3.7's default radiosity.
// counterpart: radiosity_default
#version 3.7;
global_settings {
  assumed_gamma 1.0
  radiosity { count 400 }
}
#include "room.inc"
