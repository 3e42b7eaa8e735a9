// Tests the triangle primitive: flat triangles in several orientations, one transformed (its vertices move),
// two sharing an edge (no crack between them), and shadows on the floor.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> look_at <0, 1, 0> }
background { color rgb <0.1, 0.15, 0.25> }
light_source { <-4, 8, -5> color rgb <1, 1, 1> }
light_source { <6, 3, -3> color rgb <0.3, 0.3, 0.4> }
plane { y, 0 pigment { checker color rgb <0.8, 0.8, 0.7> color rgb <0.4, 0.4, 0.35> } finish { ambient 0.1 diffuse 0.7 } }
triangle { <-3.5, 0, 0>, <-1.5, 0, 0.5>, <-2.5, 2.5, 0> pigment { color rgb <0.9, 0.3, 0.2> } finish { phong 0.5 } }
// Two triangles sharing the edge <0,0,0>–<0,2.2,0.5>: a quad folded along it.
triangle { <-1, 0, 0.5>, <0, 0, 0>, <0, 2.2, 0.5> pigment { color rgb <0.2, 0.8, 0.3> } }
triangle { <0, 0, 0>, <1, 0, 0.8>, <0, 2.2, 0.5> pigment { color rgb <0.2, 0.8, 0.3> } }
triangle { <0, 0, 0>, <2, 0, 0>, <1, 2, 0>
  scale <1, 1.2, 1> rotate y*-35 translate <1.6, 0, 0.3>
  pigment { color rgb <0.3, 0.4, 0.9> } finish { specular 0.5 }
}
