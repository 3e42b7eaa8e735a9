// Radiosity setting test (issue 19): brightness 2 (default 1): indirect light doubled.
// The room is room.inc; everything else is POV-Ray 3.7's default radiosity.
// counterpart: radiosity_default
#version 3.7;
global_settings {
  assumed_gamma 1.0
  radiosity { brightness 2 }
}
#include "room.inc"
