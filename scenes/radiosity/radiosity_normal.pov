// Radiosity setting test (issue 19): normal on (default off): samples follow the bumpy floor's perturbed normal.
// The room is room.inc; everything else is POV-Ray 3.7's default radiosity.
// counterpart: radiosity_default
#version 3.7;
global_settings {
  assumed_gamma 1.0
  radiosity { normal on }
}
#include "room.inc"
