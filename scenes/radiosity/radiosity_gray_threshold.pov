// Radiosity setting test (issue 19): gray_threshold 1 (default 0): indirect light made fully grey (no colour bleeding).
// The room is room.inc; everything else is POV-Ray 3.7's default radiosity.
// counterpart: radiosity_default
#version 3.7;
global_settings {
  assumed_gamma 1.0
  radiosity { gray_threshold 1 }
}
#include "room.inc"
