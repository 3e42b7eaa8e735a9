// Radiosity setting test (issue 19): error_bound 0.5 (default 1.8): many more samples.
// The room is room.inc; everything else is POV-Ray 3.7's default radiosity.
// counterpart: radiosity_default
#version 3.7;
global_settings {
  assumed_gamma 1.0
  radiosity { error_bound 0.5 }
}
#include "room.inc"
