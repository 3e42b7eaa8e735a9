// Tests media in a union: two overlapping hollow spheres given one interior on the union (the union hands it to
// its children, all sharing it), and a third sphere of the union, overlapping the second, with its own interior of a
// different colour. POV-Ray keeps a list of the interiors a ray is in (trace.cpp ComputeRefraction): meeting a
// surface of the interior the ray is innermost in counts as leaving it, so entering the second orange sphere while
// in the first leaves their shared interior: the overlap of the orange spheres is empty (a dark lens). In the
// overlap of the orange and the blue sphere a ray is in both interiors, and both media apply.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -7> look_at <0, 1.1, 0> }
background { color rgb <0.05, 0.05, 0.1> }
light_source { <-5, 10, -6> color rgb 0.8 }
plane { y, 0 pigment { checker color rgb 0.6 color rgb 0.1 } }
union {
  sphere { <-1.2, 1.2, 0>, 1.1 }
  sphere { <0.2, 1.2, 0.2>, 1.1 }
  sphere { <1.4, 1.6, -0.3>, 0.8 interior { media { emission <0.1, 0.6, 0.9> absorption 0.3 } } }
  pigment { color rgbt <1, 1, 1, 1> } hollow
  interior { media { emission <0.6, 0.35, 0.1> absorption <0.1, 0.3, 0.5> } }
}
