// Tests the cylinder: capped, end points in any order, along an axis and slanted, a negative radius, and a
// transformed (scaled, rotated) one; caps and sides shade with their own normals.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <1, 5, -8> look_at <0, 0.8, 0> }
background { color rgb <0.1, 0.15, 0.25> }
light_source { <-4, 8, -5> color rgb <1, 1, 1> }
light_source { <6, 3, -3> color rgb <0.3, 0.3, 0.4> }
plane { y, 0 pigment { checker color rgb <0.8, 0.8, 0.7> color rgb <0.5, 0.5, 0.45> } }
cylinder { <-3, 0, 0>, <-3, 2, 0>, 0.8 pigment { color rgb <0.9, 0.3, 0.2> } finish { phong 0.5 } }
// Second end below the first, slanted.
cylinder { <0.5, 2.2, 1>, <-0.5, 0.5, -0.5>, 0.5 pigment { color rgb <0.2, 0.8, 0.3> } finish { phong 0.5 } }
// A negative radius is the same cylinder.
cylinder { <1.5, 0.4, -1.5>, <3.5, 0.4, -1.5>, -0.4 pigment { color rgb <0.3, 0.4, 0.9> } finish { specular 0.5 } }
cylinder { 0, x, 1 scale <1, 0.3, 0.6> rotate <0, 40, 30> translate <2.5, 1.8, 2> pigment { color rgb <0.9, 0.8, 0.2> } }
