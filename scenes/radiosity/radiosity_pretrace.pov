// Radiosity setting test (issue 19): pretrace_start 0.3, pretrace_end 0.15 (defaults 0.08, 0.04): a coarser pretrace.
// The room is room.inc; everything else is POV-Ray 3.7's default radiosity.
// counterpart: radiosity_default
#version 3.7;
global_settings {
  assumed_gamma 1.0
  radiosity { pretrace_start 0.3 pretrace_end 0.15 }
}
#include "room.inc"
