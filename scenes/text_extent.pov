// Tests min_extent/max_extent of text objects (POV-Ray's union box of the glyph boxes, carried through the
// anti-crack rotation and every later transform one at a time), as the stacker sample scenes use them to centre
// letters, and inside() of text.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -6> look_at <0, 0.6, 0> }
background { color rgb <0.1, 0.15, 0.25> }
light_source { <-4, 9, -9> color rgb <1, 1, 1> }
plane { y, 0 pigment { color rgb <0.7, 0.7, 0.65> } }
#macro Framed(T, Colour)
  #local Lo = min_extent(T);
  #local Hi = max_extent(T);
  union {
    object { T pigment { color Colour } }
    cylinder { Lo, <Hi.x, Lo.y, Lo.z>, 0.015 }
    cylinder { <Lo.x, Hi.y, Lo.z>, <Hi.x, Hi.y, Lo.z>, 0.015 }
    cylinder { Lo, <Lo.x, Hi.y, Lo.z>, 0.015 }
    cylinder { <Hi.x, Lo.y, Lo.z>, <Hi.x, Hi.y, Lo.z>, 0.015 }
    sphere { Hi, 0.04 }
    pigment { color rgb <1, 1, 1> }
  }
#end
#declare A = text { ttf "timrom.ttf" "Box" 0.4, 0 scale 0.9 rotate y * -25 translate <-2.4, 0.2, 0> }
#declare B = text { ttf "cyrvetic.ttf" "fit " 0.2, <0.1, -0.05, 0> rotate z * 10 scale <1.2, 0.8, 1> translate <0.4, 0.4, -0.5> }
Framed(A, rgb <0.9, 0.5, 0.2>)
Framed(B, rgb <0.3, 0.6, 0.9>)
#declare C = text { ttf "crystal.ttf" "Q" 1, 0 }
// Centred on the origin by its extents, then lifted: the stacker scenes' centertext macro.
object { C translate -(min_extent(C) + max_extent(C)) / 2 rotate y * 30 translate <2.2, 1.8, 0>
  pigment { color rgb <0.4, 0.85, 0.4> } }
// inside(): a sphere where the point is inside the glyph's solid, a small cube where it is not.
#declare P1 = <0.1, 0.1, 0.5>;
#declare P2 = <0.35, 0.35, 0.5>;
#if (inside(C, P1)) sphere { <-1, 1.9, -1>, 0.15 pigment { color rgb <1, 0, 0> } } #end
#if (!inside(C, P2)) box { <-0.6, 1.75, -1.1>, <-0.35, 2.0, -0.85> pigment { color rgb <1, 1, 0> } } #end
