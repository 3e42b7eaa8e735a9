// Tests height fields made from a function, `function W, H { … }` (POV-Ray samples f(j/(W-1), i/(H-1), 0) into a
// 16-bit grey image while parsing): a smooth one from a float function, and one whose values leave [0, 1] and wrap
// around as POV-Ray stores them (unsigned 16-bit, unclipped), and one made from a pigment function (a 16-bit RGBA
// image whose grey is the height).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4.5, -7> look_at <0, 0.3, 0> }
light_source { <-4, 8, -5> color rgb 1 }
light_source { <5, 3, -4> color rgb 0.3 }
height_field { function 40, 30 { 0.5 + 0.4 * sin(x * 9) * cos(y * 7) } smooth
  translate <-0.5, 0, -0.5> scale <5, 1, 4> pigment { color rgb <0.9, 0.6, 0.4> } finish { phong 0.4 } }
height_field { function 25, 25 { (x - 0.5) * 3 }
  translate <-0.5, 0, -0.5> scale <2, 0.8, 2> translate <0, 0, -2.5> pigment { color rgb <0.4, 0.7, 0.9> } }
height_field { function 60, 60 { pigment { agate color_map { [0 rgb 0] [0.4 rgb <0.2, 0.3, 0.1>] [1 rgb <1, 0.9, 0.8>] }
                                            scale 0.4 } }
  smooth translate <-0.5, 0, -0.5> scale <2.4, 0.6, 2.4> translate <2.6, 0, -1.8>
  pigment { color rgb <0.5, 0.9, 0.5> } }
