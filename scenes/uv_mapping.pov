// Tests uv_mapping: the object modifier (textures at the hit's <u, v, 0>, no longer moved by the object's
// transforms) on a sphere, a box (its 4 x 3 cube layout, one mirrored by a negative scale folded into its corners),
// a torus, a mesh2 with uv_vectors and a plane (which takes the world x and y); the pigment form
// `pigment { uv_mapping … }` and the texture form `texture { uv_mapping … }`.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -11> look_at <0, 0.3, 0> angle 50 }
background { color rgb <0.2, 0.3, 0.4> }
light_source { <-5, 10, -10> color rgb <1, 1, 1> }
#declare Card = pigment { image_map { png "tex_rgb.png" } }
#declare Lit = finish { ambient 0.5 diffuse 0.6 }
plane { y, -2 uv_mapping pigment { checker color rgb <0.9, 0.9, 0.8> color rgb <0.3, 0.35, 0.4> scale 0.5 } }
sphere { 0, 1.2 uv_mapping pigment { Card } finish { Lit } rotate <20, -40, 0> translate <-3.6, 1.6, 0> }
box { <-1, -1, -1>, <1, 1, 1> uv_mapping pigment { Card } finish { Lit } rotate <-25, 35, 0> translate <-0.6, 1.8, 0> }
box { <-1, -1, -1>, <1, 1, 1> uv_mapping pigment { Card } finish { Lit }
  scale <-0.9, 0.9, 0.9> rotate <-25, -35, 0> translate <2.4, 1.8, 0> }
torus { 1, 0.4 uv_mapping pigment { checker color rgb <1, 0.8, 0.2> color rgb <0.2, 0.3, 0.9> scale <0.0625, 0.25, 1> }
  finish { Lit } rotate <-50, 0, 15> translate <4.2, 0.6, 1> }
mesh2 {
  vertex_vectors { 4, <-1, 0, 0>, <1, 0, 0>, <1, 1.5, 0>, <-1, 1.5, 0> }
  uv_vectors { 4, <0, 0>, <1, 0>, <1, 1>, <0, 1> }
  face_indices { 2, <0, 1, 2>, <0, 2, 3> }
  uv_mapping pigment { Card } finish { ambient 1 diffuse 0 } rotate y * -20 translate <-2.8, -1.6, -1>
}
sphere { 0, 1 pigment { uv_mapping checker color rgb <0.9, 0.3, 0.3> color rgb <1, 1, 1> scale <0.125, 0.25, 1> }
  finish { Lit } rotate x * 30 translate <0.2, -0.9, -1> }
sphere { 0, 1 texture { uv_mapping pigment { Card } finish { ambient 0.2 diffuse 0.7 phong 0.5 } }
  scale <1.2, 0.9, 1> translate <2.8, -1, -1.5> }
