// Tests the facets normal (POV-Ray's normal.cpp facets): without coords the normal becomes the random cube point
// (crackle's) nearest to normal/size (left: size 0.2; middle: metric 1, POV-Ray's sum without absolute values,
// scaled); with coords the normal gains coords times the vector noise across it at the point nearest to P/size
// (the floor: coords 0.5; right: coords 1 with metric 3).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -5> look_at <0, 0.6, 0> angle 50 }
light_source { <-3, 6, -5> color rgb 1 }
plane { y, 0 pigment { rgb 0.7 } normal { facets coords 0.5 size 0.3 } }
sphere { <-1.3, 0.8, 0>, 0.8 pigment { rgb <0.9, 0.4, 0.2> } normal { facets size 0.2 } finish { phong 0.8 } }
sphere { <0.5, 0.8, 0>, 0.8 pigment { rgb <0.2, 0.6, 0.9> } normal { facets size 0.15 metric 1 scale 1.5 } finish { phong 0.8 } }
sphere { <2, 0.8, 0.5>, 0.8 pigment { rgb <0.3, 0.9, 0.3> } normal { facets coords 1 size 0.1 metric 3 } finish { phong 0.8 } }
