// Radiosity setting test (issue 19): low_error_factor 0.1 (default 0.5): a much tighter error bound in the pretrace.
// The room is room.inc; everything else is POV-Ray 3.7's default radiosity.
// counterpart: radiosity_default
#version 3.7;
global_settings {
  assumed_gamma 1.0
  radiosity { low_error_factor 0.1 }
}
#include "room.inc"
