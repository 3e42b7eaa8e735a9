// Radiosity setting test (issue 19): minimum_reuse 0.15 (default 0.015): samples may not be packed closer, corners blotchy.
// The room is room.inc; everything else is POV-Ray 3.7's default radiosity.
// counterpart: radiosity_default
#version 3.7;
global_settings {
  assumed_gamma 1.0
  radiosity { minimum_reuse 0.15 }
}
#include "room.inc"
