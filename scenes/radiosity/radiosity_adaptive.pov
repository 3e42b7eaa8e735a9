// Radiosity setting test (issue 19): nearest_count's second value (adaptive pretrace): with 5, 3 and pretrace_end
// 0.01 (four passes), blocks and sub-blocks whose points already find an average 4·Σw of 3 stop refining early.
// The room is room.inc; everything else is POV-Ray 3.7's default radiosity.
// counterpart: radiosity_pretrace_end
#version 3.7;
global_settings {
  assumed_gamma 1.0
  radiosity { nearest_count 5, 3 pretrace_end 0.01 }
}
#include "room.inc"
