// Tests media in a difference: a hollow box of glowing, absorbing media with a sphere and a cylinder cut out of it
// (the cut surfaces bound the media: rays through the holes cross no media there) over a checker floor.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -7> look_at <0, 1.1, 0> }
background { color rgb <0.05, 0.05, 0.1> }
light_source { <-5, 10, -6> color rgb 0.8 }
plane { y, 0 pigment { checker color rgb 0.6 color rgb 0.1 } }
difference {
  box { <-2, 0.01, -1>, <2, 2.4, 1> }
  sphere { <-0.6, 1.3, -0.4>, 0.9 }
  cylinder { <1.2, 1.2, -2>, <1.2, 1.2, 2>, 0.45 }
  pigment { color rgbt <1, 1, 1, 1> } hollow
  interior { media { emission <0.7, 0.4, 0.15> absorption <0.2, 0.4, 0.6> } }
  rotate y*-15
}
