// Radiosity setting test (issue 19): always_sample on (default off): the final render still makes new samples (on the coarse pretrace of radiosity_pretrace, where it matters).
// The room is room.inc; everything else is POV-Ray 3.7's default radiosity.
// counterpart: radiosity_pretrace
#version 3.7;
global_settings {
  assumed_gamma 1.0
  radiosity { always_sample on pretrace_start 0.3 pretrace_end 0.15 }
}
#include "room.inc"
