// Radiosity setting test (issue 19): pretrace_end 0.01 (default 0.04): four pretrace passes instead of two; the
// counterpart of radiosity_adaptive (the same without adaptive refinement).
// The room is room.inc; everything else is POV-Ray 3.7's default radiosity.
// counterpart: radiosity_default
#version 3.7;
global_settings {
  assumed_gamma 1.0
  radiosity { pretrace_end 0.01 }
}
#include "room.inc"
