// Radiosity setting test (issue 19): POV-Ray's default radiosity settings (the counterpart of most other radiosity_*.pov scenes).
// The room is room.inc; everything else is POV-Ray 3.7's default radiosity.
// counterpart: radiosity_default
#version 3.7;
global_settings {
  assumed_gamma 1.0
  radiosity {}
}
#include "room.inc"
