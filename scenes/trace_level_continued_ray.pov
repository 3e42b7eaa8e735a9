// A ray continued through an ior-1 surface at the deepest trace level sees black: POV-Ray's TraceRay tests the
// trace level the continued ray shares with its parent against max_trace_level before tracing it (trace.cpp), so
// with max_trace_level 2 the sphere seen directly shows the floor through it, the one seen in the mirror (level 2)
// shows black where the continued ray would go, and a glass sphere (ior 1.5, a new level) shows black as well.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 2 }
camera { location <0, 2, -6> look_at <0, 1, 0> }
background { color rgb <0.3, 0.4, 0.6> }
light_source { <-4, 8, -6> color rgb 1 }
plane { y, 0 pigment { checker color rgb 0.9 color rgb 0.3 } }
sphere { <-1.3, 1, -1>, 0.8 pigment { color rgbt <1, 0.9, 0.8, 0.7> } }
sphere { <1.3, 1, -1>, 0.8 pigment { color rgbf <1, 1, 1, 0.9> } interior { ior 1.5 } }
box { <-4, 0, 0>, <4, 3, 0.2> translate z * 2 pigment { color rgb 0.05 } finish { reflection 0.8 } }
