// Radiosity setting test (issue 19): max_sample 0.2 (default: no limit): bright sample rays are clamped.
// The room is room.inc; everything else is POV-Ray 3.7's default radiosity.
// counterpart: radiosity_default
#version 3.7;
global_settings {
  assumed_gamma 1.0
  radiosity { max_sample 0.2 }
}
#include "room.inc"
