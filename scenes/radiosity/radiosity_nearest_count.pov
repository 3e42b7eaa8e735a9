// Radiosity setting test (issue 19): nearest_count 1 (default 5): each point uses only the nearest sample (on count 150, error_bound 3, where reuse is wide).
// The room is room.inc; everything else is POV-Ray 3.7's default radiosity.
// counterpart: radiosity_error_bound3
#version 3.7;
global_settings {
  assumed_gamma 1.0
  radiosity { count 150 error_bound 3 nearest_count 1 }
}
#include "room.inc"
