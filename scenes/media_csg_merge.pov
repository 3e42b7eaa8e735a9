// Tests media in a merge: the scene of media_csg_union with merge instead of union. A merge drops the surfaces
// inside each other, so the overlap of the two orange spheres is filled like the rest (no dark lens). The blue
// sphere has its own interior: a ray entering the blue sphere and leaving through the orange sphere's surface does
// not find the orange interior in its list, so POV-Ray counts it as entering (trace.cpp ComputeRefraction) and
// the ray carries both media on to the floor (the bright crescent).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -7> look_at <0, 1.1, 0> }
background { color rgb <0.05, 0.05, 0.1> }
light_source { <-5, 10, -6> color rgb 0.8 }
plane { y, 0 pigment { checker color rgb 0.6 color rgb 0.1 } }
merge {
  sphere { <-1.2, 1.2, 0>, 1.1 }
  sphere { <0.2, 1.2, 0.2>, 1.1 }
  sphere { <1.4, 1.6, -0.3>, 0.8 interior { media { emission <0.1, 0.6, 0.9> absorption 0.3 } } }
  pigment { color rgbt <1, 1, 1, 1> } hollow
  interior { media { emission <0.6, 0.35, 0.1> absorption <0.1, 0.3, 0.5> } }
}
