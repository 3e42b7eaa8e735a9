// Tests smooth_triangle: vertex normals interpolated across the face (a fan of smooth triangles forming a rounded
// cone), a transformed smooth triangle, and one whose normals point to both sides of its face (POV-Ray finds it
// degenerate and never hits it: the red one must not appear).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> look_at <0, 1, 0> }
background { color rgb <0.1, 0.15, 0.25> }
light_source { <-4, 8, -5> color rgb <1, 1, 1> }
light_source { <6, 3, -3> color rgb <0.3, 0.3, 0.4> }
plane { y, 0 pigment { checker color rgb <0.8, 0.8, 0.7> color rgb <0.4, 0.4, 0.35> } finish { ambient 0.1 diffuse 0.7 } }
#declare N = 8;
#declare Apex = <0, 2.4, 0>;
union {
  #for (I, 0, N - 1)
    #declare A0 = 2 * pi * I / N;
    #declare A1 = 2 * pi * (I + 1) / N;
    #declare P0 = <cos(A0), 0.2, sin(A0)>;
    #declare P1 = <cos(A1), 0.2, sin(A1)>;
    smooth_triangle { P0, <cos(A0), 0.45, sin(A0)>, P1, <cos(A1), 0.45, sin(A1)>, Apex, <cos(A0 + pi / N), 0.45, sin(A0 + pi / N)> }
  #end
  translate <-1.6, 0, 0.5>
  pigment { color rgb <0.3, 0.8, 0.4> } finish { phong 0.6 phong_size 30 }
}
smooth_triangle { <0, 0, 0>, <-1, 0.3, -1>, <2, 0, 0>, <1, 0.3, -1>, <1, 2, 0>, <0, 1, -0.5>
  scale <1, 1.1, 1> rotate y*-30 translate <1.2, 0.1, 0.5>
  pigment { color rgb <0.3, 0.4, 0.9> } finish { phong 0.6 }
}
// Normals on both sides of the face: never hit.
smooth_triangle { <-0.5, 2.6, 0>, <0, 0, -1>, <0.5, 2.6, 0>, <0, 0, 1>, <0, 3.3, 0>, <0, 0, -1>
  pigment { color rgb <1, 0, 0> }
}
