// Radiosity setting test (issue 19): recursion_limit 1 (default 2): one bounce of indirect light only.
// The room is room.inc; everything else is POV-Ray 3.7's default radiosity.
// counterpart: radiosity_default
#version 3.7;
global_settings {
  assumed_gamma 1.0
  radiosity { recursion_limit 1 }
}
#include "room.inc"
