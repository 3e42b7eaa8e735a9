// Radiosity setting test (issue 19): adc_bailout 0.5 (default 0.01): sample rays bail out early.
// The room is room.inc; everything else is POV-Ray 3.7's default radiosity.
// counterpart: radiosity_default
#version 3.7;
global_settings {
  assumed_gamma 1.0
  radiosity { adc_bailout 0.5 }
}
#include "room.inc"
