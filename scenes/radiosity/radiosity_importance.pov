// Radiosity setting test (issue 19): importance: #default importance 0.05 (default 1) for every object but the sphere (importance 1), on count 400: sample rays that hit low-importance objects are mostly dropped.
// The room is room.inc; everything else is POV-Ray 3.7's default radiosity.
// counterpart: radiosity_count400
#version 3.7;
global_settings {
  assumed_gamma 1.0
  radiosity { count 400 }
}
#default { radiosity { importance 0.05 } }
#declare Sphere_Importance = 1;
#include "room.inc"
