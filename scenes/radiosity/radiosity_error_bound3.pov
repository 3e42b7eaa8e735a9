// Radiosity setting test (issue 19): error_bound 3 (default 1.8): fewer samples, reused further (on count 150).
// The room is room.inc; everything else is POV-Ray 3.7's default radiosity.
// counterpart: radiosity_count
#version 3.7;
global_settings {
  assumed_gamma 1.0
  radiosity { count 150 error_bound 3 }
}
#include "room.inc"
