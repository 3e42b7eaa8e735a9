// Tests mesh: a closed octahedron whose triangles carry their own textures (texture { T_id }), one blended
// texture_list triangle, triangles without a texture taking the mesh's, a smooth_triangle inside the mesh, a
// degenerate triangle (skipped), and inside_vector.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> look_at <0, 1, 0> }
background { color rgb <0.1, 0.15, 0.25> }
light_source { <-4, 8, -5> color rgb <1, 1, 1> }
light_source { <6, 3, -3> color rgb <0.3, 0.3, 0.4> }
plane { y, 0 pigment { checker color rgb <0.8, 0.8, 0.7> color rgb <0.4, 0.4, 0.35> } finish { ambient 0.1 diffuse 0.7 } }
#declare Red = texture { pigment { color rgb <0.9, 0.2, 0.15> } finish { phong 0.5 } }
#declare Green = texture { pigment { color rgb <0.2, 0.8, 0.3> } }
#declare Blue = texture { pigment { color rgb <0.2, 0.3, 0.9> } finish { specular 0.4 } }
#declare Top = <0, 2, 0>;
#declare Bottom = <0, 0, 0>;
#declare E = <1, 1, 0>;
#declare W = <-1, 1, 0>;
#declare S = <0, 1, -1>;
#declare Nn = <0, 1, 1>;
mesh {
  triangle { Top, W, S texture { Red } }
  triangle { Top, S, E texture_list { Red Green Blue } }
  triangle { Top, E, Nn texture { Green } }
  triangle { Top, Nn, W }
  triangle { Bottom, S, W texture { Blue } }
  smooth_triangle { Bottom, <0, -1, 0>, E, <1, 0, 0>, S, <0, 0, -1> texture { Green } }
  triangle { Bottom, Nn, E }
  triangle { Bottom, W, Nn texture { Red } }
  triangle { Bottom, Bottom, E }
  inside_vector <0, 0, 1>
  pigment { color rgb <0.9, 0.8, 0.3> }
  rotate y*-25 translate <-0.3, 0, 0>
}
