// Tests CSG intersection: a rounded cube (box ∩ sphere) textured per child, so each face shows which child's surface
// it is, a lens (two spheres) and a wedge cut from a sphere by two planes (unbounded children).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <1, 4, -7> look_at <0, 0.8, 0> }
background { color rgb <0.1, 0.15, 0.25> }
light_source { <-4, 8, -5> color rgb 1 }
light_source { <6, 3, -4> color rgb 0.3 }
plane { y, 0 pigment { checker rgb 0.9 rgb 0.6 } }
intersection {
  box { -1, 1 pigment { rgb <0.9, 0.3, 0.2> } }
  sphere { 0, 1.35 pigment { rgb <0.2, 0.5, 0.9> } }
  finish { phong 0.4 }
  rotate y*30 translate <-2.2, 1, 0.5>
}
intersection {
  sphere { <0, 0, -0.6>, 1.1 }
  sphere { <0, 0, 0.6>, 1.1 }
  pigment { rgb <0.3, 0.8, 0.3> }
  rotate <0, -50, 20> translate <0.3, 0.9, -0.5>
}
intersection {
  sphere { 0, 1 }
  plane { x, 0 }
  plane { z, 0 rotate y*-40 }
  pigment { rgb <0.9, 0.8, 0.3> }
  finish { specular 0.6 }
  translate <2.4, 1, 0.3>
}
