// triangle, smooth_triangle, polygon, mesh and mesh2 as the parser describes them: flat arrays, shared data,
// POV-Ray's degenerate and closing rules, and located errors for bad counts and indices.
#include <gtest/gtest.h>

#include "tests/parser/parse_helpers.hpp"

namespace povtrace::test {
namespace {

const Mesh& mesh_of(const SceneDescription& s, std::size_t i = 0) { return std::get<Mesh>(s.objects.at(i).shape); }

TEST(MeshParse, MeshMergesEqualVerticesAndStoresThemInSinglePrecision) {
  const SceneDescription s = parse(
      "#version 3.7;\n"
      "mesh { triangle { <0,0,0>, <1,0,0>, <0,1,0> } triangle { <1,0,0>, <1,1,0>, <0,1,0> } "
      "triangle { <0.1,0,0>, <0.1,0,0>, <0,1,0> } }\n");
  const MeshData& d = *mesh_of(s).data;
  EXPECT_EQ(d.triangle_count(), 2u);         // the degenerate one is dropped
  EXPECT_EQ(d.vertices.size(), 4u * 3);      // four distinct vertices
  EXPECT_EQ(d.faces, (std::vector<std::uint32_t>{0, 1, 2, 1, 3, 2}));
  const SceneDescription t = parse("#version 3.7;\nmesh { triangle { <0.1,0,0>, <1,0,0>, <0,1,0> } }\n");
  EXPECT_EQ(mesh_of(t).data->vertices[0], 0.1f);   // 0.100000001490…, as POV-Ray's SNGL_VECT
}

TEST(MeshParse, DegenerateTrianglesInAMeshWarnOnce) {
  Messages m;
  parse("#version 3.7;\nmesh { triangle { 0, 0, x } triangle { 0, x, y } triangle { y, y, y } }\n", &m);
  ASSERT_EQ(m.items.size(), 1u);
  EXPECT_NE(m.items[0].find("2 degenerate triangle(s)"), std::string::npos) << m.items[0];
}

TEST(MeshParse, PerTriangleTexturesAndTextureList) {
  const SceneDescription s = parse(
      "#version 3.7;\n#declare A = texture { pigment { rgb 1 } }\n#declare B = texture { pigment { rgb 0.5 } }\n"
      "mesh { triangle { 0, x, y } triangle { 0, x, z texture { A } } "
      "triangle { 0, y, z uv_vectors <0,0>, <1,0>, <0,1> texture_list { B A B } } inside_vector <0, 0, 2> }\n");
  const Mesh& mesh = mesh_of(s);
  ASSERT_EQ(mesh.textures.size(), 2u);
  EXPECT_EQ(mesh.data->face_textures, (std::vector<std::int32_t>{-1, -1, -1, 0, -1, -1, 1, 0, 1}));
  ASSERT_TRUE(mesh.data->inside_vector.has_value());
  EXPECT_EQ(*mesh.data->inside_vector, (Vec3{0, 0, 1}));
}

TEST(MeshParse, DeclaredMeshCopiesShareTheirData) {
  const SceneDescription s = parse(
      "#version 3.7;\n#declare M = mesh { triangle { 0, x, y } }\n"
      "#for (I, 1, 1000) object { M translate I*x } #end\n");
  ASSERT_EQ(s.objects.size(), 1000u);
  for (const Object& o : s.objects) EXPECT_EQ(std::get<Mesh>(o.shape).data.get(), mesh_of(s).data.get());
}

TEST(MeshParse, Mesh2NormalsTexturesAndFlatFaces) {
  const SceneDescription s = parse(
      "#version 3.7;\nmesh2 { vertex_vectors { 4, 0, x, y, z } normal_vectors { 2, <0,0,-2>, <1,0,0> }\n"
      "texture_list { 2, texture { pigment { rgb 1 } } texture { pigment { rgb 0 } } }\n"
      "face_indices { 3, <0,1,2>, 1, <0,1,3>, 0, 1, 0, <1,2,3> } normal_indices { 2, <0,1,0>, <0,0,0> } }\n");
  const MeshData& d = *mesh_of(s).data;
  EXPECT_EQ(d.normal(0), (Vec3{0, 0, -1}));   // normalised
  EXPECT_EQ(d.face_textures, (std::vector<std::int32_t>{1, -1, -1, 0, 1, 0, -1, -1, -1}));
  const std::uint32_t flat = MeshData::flat;
  EXPECT_EQ(d.face_normals, (std::vector<std::uint32_t>{0, 1, 0, flat, flat, flat, flat, flat, flat}));
}

TEST(MeshParse, Mesh2IndexOutOfRangeIsLocatedAtTheFace) {
  const ParseError e = parse_error(
      "#version 3.7;\nmesh2 { vertex_vectors { 3, 0, x, y }\n  face_indices { 2, <0,1,2>, <0,1,3> } }\n");
  EXPECT_EQ(e.location().line, 3);
  EXPECT_EQ(e.location().column, 30);
  EXPECT_NE(e.bare_message().find("index 3 out of range"), std::string::npos) << e.bare_message();
  const ParseError t = parse_error(
      "#version 3.7;\nmesh2 { vertex_vectors { 3, 0, x, y } texture_list { 1, texture { } }\n"
      "face_indices { 1, <0,1,2>, 1 } }\n");
  EXPECT_EQ(t.location().line, 3);
  EXPECT_EQ(t.location().column, 28);
  const ParseError n = parse_error(
      "#version 3.7;\nmesh2 { vertex_vectors { 3, 0, x, y } normal_vectors { 1, y }\n"
      "face_indices { 1, <0,1,2> } normal_indices { 1, <0,0,-1> } }\n");
  EXPECT_NE(n.bare_message().find("normal index -1 out of range"), std::string::npos) << n.bare_message();
}

TEST(MeshParse, Mesh2WrongCountsAreErrors) {
  const ParseError fewer =
      parse_error("#version 3.7;\nmesh2 { vertex_vectors { 4, 0, x, y } face_indices { 1, <0,1,2> } }\n");
  EXPECT_NE(fewer.bare_message().find("declares 4 vectors but lists only 3"), std::string::npos)
      << fewer.bare_message();
  EXPECT_EQ(fewer.location().column, 37);
  const ParseError more =
      parse_error("#version 3.7;\nmesh2 { vertex_vectors { 3, 0, x, y } face_indices { 1, <0,1,2>, <0,2,1> } }\n");
  EXPECT_NE(more.bare_message().find("declares 1 face but lists more"), std::string::npos) << more.bare_message();
  parse_error("#version 3.7;\nmesh2 { face_indices { 1, <0,1,2> } }\n");
  parse_error("#version 3.7;\nmesh { }\n");
}

TEST(MeshParse, PolygonClosesItsSubPolygonsAndWarnsWhenOpen) {
  Messages m;
  const SceneDescription s = parse("#version 3.7;\npolygon { 3, <0,0>, <1,0>, <0,1> }\n", &m);
  EXPECT_EQ(std::get<Polygon>(s.objects[0].shape).points.size(), 4u);
  ASSERT_EQ(m.items.size(), 1u);
  EXPECT_NE(m.items[0].find("not closed"), std::string::npos);
  Messages quiet;
  const SceneDescription h = parse(
      "#version 3.7;\npolygon { 8, <0,0>, <3,0>, <0,3>, <0,0>, <1,1>, <1.5,1>, <1,1.5>, <1,1> }\n", &quiet);
  EXPECT_TRUE(quiet.items.empty());
  EXPECT_FALSE(std::get<Polygon>(h.objects[0].shape).degenerate);
  EXPECT_EQ(parse_error("#version 3.7;\npolygon { 2, 0, x }\n").location().column, 11);
}

TEST(MeshParse, SmoothTriangleWithNormalsOnBothSidesIsDegenerate) {
  Messages m;
  const SceneDescription s =
      parse("#version 3.7;\nsmooth_triangle { 0, z, x, -z, y, z }\nsmooth_triangle { 0, z, x, z, y, <0,1,1> }\n", &m);
  EXPECT_TRUE(std::get<Triangle>(s.objects[0].shape).degenerate);
  EXPECT_FALSE(std::get<Triangle>(s.objects[1].shape).degenerate);
  ASSERT_EQ(m.items.size(), 1u);
}

}  // namespace
}  // namespace povtrace::test
