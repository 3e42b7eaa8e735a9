// A sphere that moves and changes colour with the clock, on a checker floor: the animation identifiers
// (clock, frame_number, clock_delta) drive the scene. Used by the MPI frames tests.
// Rendered with +KFI1 +KFF6 +KC (tests/mpi/CMakeLists.txt).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -5> look_at <0, 0.5, 0> }
light_source { <-3, 6, -4> color rgb 1 }
plane { y, 0 pigment { checker rgb 0.8 rgb 0.2 } }
sphere { <2 * clock - 1, 0.5 + 0.1 * frame_number, 0>, 0.5
  pigment { rgb <clock, 0.5, 1 - clock> } finish { phong 0.6 } }
box { <-0.2, 0, 1>, <0.2, clock_delta * 10, 1.4> pigment { rgb 0.7 } }
#debug concat("frame ", str(frame_number, 0, 0), " clock ", str(clock, 0, 4), "\n")
