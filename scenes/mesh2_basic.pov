// Tests mesh2: vertex_vectors with normal_vectors (one per vertex, smooth shading without normal_indices), a
// texture_list with per-face texture indices (one index, and three indices blended across the face), faces
// without an index taking the mesh's texture, and a second mesh2 with explicit normal_indices covering only its
// first faces.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> look_at <0, 1, 0> }
background { color rgb <0.1, 0.15, 0.25> }
light_source { <-4, 8, -5> color rgb <1, 1, 1> }
light_source { <6, 3, -3> color rgb <0.3, 0.3, 0.4> }
plane { y, 0 pigment { checker color rgb <0.8, 0.8, 0.7> color rgb <0.4, 0.4, 0.35> } finish { ambient 0.1 diffuse 0.7 } }
// A rounded pyramid: apex, four base corners; normals point away from the centre.
mesh2 {
  vertex_vectors { 5, <0, 2, 0>, <-1, 0, -1>, <1, 0, -1>, <1, 0, 1>, <-1, 0, 1> }
  normal_vectors { 5, <0, 1, 0>, <-1, 0.3, -1>, <1, 0.3, -1>, <1, 0.3, 1>, <-1, 0.3, 1> }
  texture_list { 3,
    texture { pigment { color rgb <0.9, 0.2, 0.15> } finish { phong 0.5 } },
    texture { pigment { color rgb <0.2, 0.8, 0.3> } },
    texture { pigment { color rgb <0.2, 0.3, 0.9> } }
  }
  face_indices { 4,
    <0, 1, 2>, 0,
    <0, 2, 3>, 0, 1, 2,
    <0, 3, 4>, 2,
    <0, 4, 1>
  }
  pigment { color rgb <0.9, 0.8, 0.3> }
  rotate y*20 translate <-1.5, 0, 0.3>
}
// Two faces of a folded sheet: only the first has normal indices (smooth), the second is flat.
mesh2 {
  vertex_vectors { 4, <0, 0, 0>, <1.5, 0, 0>, <0, 2, 0.3>, <1.5, 2, -0.6> }
  normal_vectors { 2, <-0.5, 0, -1>, <0.5, 0.2, -1> }
  face_indices { 2, <0, 1, 2>, <1, 3, 2> }
  normal_indices { 1, <0, 1, 0> }
  pigment { color rgb <0.6, 0.5, 0.9> } finish { phong 0.4 }
  translate <0.9, 0, 0>
}
