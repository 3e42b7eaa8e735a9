// Tests blob components with textures of their own (POV-Ray's Blob::Determine_Textures): at each point every
// component whose field reaches it shades with its texture (the blob's where it has none), weighted by |field|
// scaled to sum 1, in single precision as POV-Ray. A pigment-only component edits a copy of the #default texture;
// transforms after a component's texture move it (the checker), the blob's rotate moves them all; a component of
// negative strength adds its |field| to the weights; a filtering component tints the shadow by its share, the
// shadow ray looking again from each blob crossing (a blob reports only its first stretch of crossings).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -6> look_at <0, 0.5, 0> angle 45 }
light_source { <-4, 8, -5> color rgb 1 }
plane { y, -1 pigment { checker rgb 0.9 rgb 0.3 } }
blob { threshold 0.6
  sphere { <-0.8, 0.5, 0>, 1, 1 pigment { rgb <1, 0.2, 0.1> } }
  sphere { <0.8, 0.5, 0>, 1, 1 texture { pigment { rgb <0.1, 0.3, 1> filter 0.7 } finish { phong 0.8 } } translate y*0.2 }
  cylinder { <0, -0.5, 0>, <0, 1.5, 0.5>, 0.6, 1 }
  sphere { <0, 1.3, -0.5>, 0.7, 1 pigment { checker rgb 1 rgb 0 scale 0.2 } scale <1, 1.3, 1> }
  sphere { <1.6, -0.4, -0.6>, 0.6, -0.5 }
  pigment { rgb <0.2, 0.9, 0.2> }
  rotate y*20
}
