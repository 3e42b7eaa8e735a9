// Radiosity setting test (issue 19): a fog in the room with media off (the default): camera rays see the fog,
// radiosity sample rays do not (POV-Ray clears the volume quality bit for them).
// The room is room.inc; everything else is POV-Ray 3.7's default radiosity.
// counterpart: radiosity_default
#version 3.7;
global_settings {
  assumed_gamma 1.0
  radiosity { }
}
fog { distance 2.5 color rgb <0.9, 0.6, 0.3> }
#include "room.inc"
