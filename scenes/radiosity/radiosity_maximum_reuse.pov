// Radiosity setting test (issue 19): maximum_reuse 0.04 (default 0.2): samples reach less far, so many more are made.
// The room is room.inc; everything else is POV-Ray 3.7's default radiosity.
// counterpart: radiosity_default
#version 3.7;
global_settings {
  assumed_gamma 1.0
  radiosity { maximum_reuse 0.04 }
}
#include "room.inc"
