// Radiosity setting test (issue 19): emission as the light source: no light_source, a ceiling panel with finish { emission 4 } lights the room.
// The room is room.inc; everything else is POV-Ray 3.7's default radiosity.
// counterpart: radiosity_default
#version 3.7;
global_settings {
  assumed_gamma 1.0
  radiosity {}
}
#declare Room_Emission_Only = 1;
#include "room.inc"
