// Radiosity setting test (issue 19): media on (default off): radiosity sample rays see the room's fog too.
// The room is room.inc; everything else is POV-Ray 3.7's default radiosity.
// counterpart: radiosity_fog
#version 3.7;
global_settings {
  assumed_gamma 1.0
  radiosity { media on }
}
fog { distance 2.5 color rgb <0.9, 0.6, 0.3> }
#include "room.inc"
