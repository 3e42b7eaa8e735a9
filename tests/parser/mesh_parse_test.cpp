// triangle, smooth_triangle, polygon, mesh and mesh2 as the parser describes them: flat arrays, shared data,
// POV-Ray's degenerate and closing rules, and located errors for bad counts and indices.
#include <cmath>

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

// Literal items are read straight from the text (parser/lexing/mesh_scan.hpp); a comment before an item sends it through
// the ordinary token reading. Both must give the same arrays, and the same messages.
void expect_same_mesh(const std::string& literal, const std::string& ordinary) {
  Messages ml, mo;
  const SceneDescription a = parse(literal, &ml), b = parse(ordinary, &mo);
  ASSERT_EQ(a.objects.size(), b.objects.size());
  for (std::size_t i = 0; i < a.objects.size(); ++i) {
    const MeshData &x = *mesh_of(a, i).data, &y = *mesh_of(b, i).data;
    EXPECT_EQ(x.vertices, y.vertices);
    EXPECT_EQ(x.normals, y.normals);
    EXPECT_EQ(x.faces, y.faces);
    EXPECT_EQ(x.face_normals, y.face_normals);
    EXPECT_EQ(x.face_textures, y.face_textures);
    EXPECT_EQ(x.uvs, y.uvs);
    EXPECT_EQ(x.face_uvs, y.face_uvs);
    for (std::size_t v = 0; v < x.vertices.size() && v < y.vertices.size(); ++v)   // -0 stays -0
      EXPECT_EQ(std::signbit(x.vertices[v]), std::signbit(y.vertices[v])) << v;
  }
  // The same warnings (their source lines differ by the comments).
  auto bare = [](const Messages& m) {
    std::vector<std::string> out;
    for (const std::string& t : m.items) {
      const std::size_t at = t.find("warning: ");
      out.push_back(t.substr(at, t.find('\n', at) - at));
    }
    return out;
  };
  EXPECT_EQ(bare(ml), bare(mo));
}

std::string with_comments_before(const std::string& text, const std::string& item_start) {
  std::string out;
  for (std::size_t at = 0;;) {
    std::size_t next = text.find(item_start, at);
    while (next != std::string::npos && next > 0 && text[next - 1] == '_') next = text.find(item_start, next + 1);
    out += text.substr(at, next - at);
    if (next == std::string::npos) return out;
    out += "/**/";
    at = next;
    out += item_start;
    at += item_start.size();
  }
}

TEST(MeshParse, LiteralTrianglesReadAsTheTokenStreamReadsThem) {
  const std::string items =
      "triangle { <4.000000, 2.860559, -0.000000>, <3.999921,2.874974,0.020587>,<4.000173, 2.885272, 0.013379> }\n"
      "triangle{<-.5, 5., 1e-3>, < 1E+2 , -2.5e-1, 0 > <7, 8, 9>}\n"
      "  triangle { <4.000000, 2.860559, 0.000000>, <1, 1, 1>, <7, 8, 9> }\r\n"
      "smooth_triangle { <0, 0, 0>, <0, 0, 0>, <1, 0, 0>, <0, 0, 1>, <0, 1, 0>, <0, 0, 2> }\n"
      "smooth_triangle { <0, 0, 0>, <0, 0, 1>, <1, 0, 0>, <0, 0, 1>, <0, 1, 0>, <0, 0, 1> }\n"
      "smooth_triangle { <0, 0, 0>, <0, 1, 1>, <1, 0, 0>, <0, 0, 1>, <0, 1, 0>, <1, 0, 1> }\n"
      "triangle { <1, 1, 1>, <1, 1, 1>, <2, 2, 2> }\n"                     // degenerate: counted, dropped
      "triangle { <0, 0, 0>, <1, 0, 0>, <0, 1, 0> uv_vectors <0,0>, <1,0>, <0,1> }\n"   // not literal: ordinary
      "triangle { <0, 0, 0>, <2, 0, 0>*2, <0, 1, 0> }\n"                   // an expression: ordinary
      "triangle { <0, 0, 0>, <3, 0, 0>, <0, 1, 0>, }\n"                    // no: ordinary, which refuses it
      "triangle { <0, 0, 0>, <1.5, 0, 0>, <0, 1, 0> }\n"
      "triangle { <0, 0, 0>, <1.5, 0, 0>, <0, 1, 0> } inside_vector <0, 0, 1>\n";
  // The one with a trailing comma is an error either way.
  parse_error("#version 3.7;\nmesh {\n" + items + "}\n");
  std::string good = items;
  const std::string refused = "triangle { <0, 0, 0>, <3, 0, 0>, <0, 1, 0>, }\n";
  good.erase(good.find(refused), refused.size());
  const std::string scene = "#version 3.7;\nmesh {\n" + good + "}\n";
  expect_same_mesh(scene, with_comments_before(with_comments_before(scene, "triangle"), "smooth_triangle"));
}

TEST(MeshParse, LiteralItemsInLoopsAndMacrosAreReplayed) {
  const std::string mesh = "mesh { triangle { <0, 0, 0>, <1, 0, 0>, <0, 1, 0> } triangle { <1, 0, 0>, <1, 1, 0>, "
                           "<0, 1, 0> } triangle { <5, 0, 0>, <1, 1, 0>, <0, 1, 0> } }\n";
  const std::string mesh2 = "mesh2 { vertex_vectors { 4, <0, 0, 0>, <1, 0, 0>, <0, 1, 0>, <1, 1, 0> } "
                            "face_indices { 2, <0, 1, 2>, <1, 3, 2> } }\n";
  for (const std::string& m : {mesh, mesh2}) {
    const SceneDescription once = parse("#version 3.7;\n" + m);
    const SceneDescription loop = parse("#version 3.7;\n#declare I = 0;\n#while (I < 3)\n" + m +
                                        "#declare I = I + 1;\n#end\n#for (J, 1, 2)\n" + m + "#end\n");
    const SceneDescription macro = parse("#version 3.7;\n#macro M() " + m + " #end\nM() M()\n");
    ASSERT_EQ(loop.objects.size(), 5u);
    ASSERT_EQ(macro.objects.size(), 2u);
    for (std::size_t i = 0; i < 5; ++i) EXPECT_EQ(mesh_of(loop, i).data->faces, mesh_of(once).data->faces);
    for (std::size_t i = 0; i < 2; ++i) EXPECT_EQ(mesh_of(macro, i).data->vertices, mesh_of(once).data->vertices);
  }
}

TEST(MeshParse, LiteralMesh2ItemsReadAsTheTokenStreamReadsThem) {
  const std::string scene =
      "#version 3.7;\nmesh2 {\n vertex_vectors { 6\n  <0, 0, 0>, <1, 0, -0.0>\n  <0, 1.5e0, 0>, <1, 1, 0>,\n"
      "  <2, 0, 0>, x }\n normal_vectors { 3, <0, 0, -2>, <0, 0, 0>, <0, 1, 1> }\n"
      " texture_list { 2, texture { pigment { rgb 1 } } texture { pigment { rgb 0 } } }\n"
      " face_indices { 5, <0, 1, 2>, <1.9, 3, 2>, <1, 4, 3> 1, <2, 3, 4>, <0, 4, 5>, }\n"
      " normal_indices { 4, <0, 1, 2>, <2, 2, 2>, <0, 0, 1> <1, 2, 0> }\n}\n";
  std::string ordinary = scene;
  for (std::size_t at = 0; (at = ordinary.find('<', at)) != std::string::npos; at += 5) ordinary.insert(at, "/**/");
  expect_same_mesh(scene, ordinary);
  // An index out of range in a literal face is still reported where it stands.
  const ParseError e = parse_error(
      "#version 3.7;\nmesh2 { vertex_vectors { 3, <0, 0, 0>, <1, 0, 0>, <0, 1, 0> }\n"
      "  face_indices { 3, <0, 1, 2>, <0, 2, 1>, <0, 1, 3> } }\n");
  EXPECT_EQ(e.location().line, 3);
  EXPECT_EQ(e.location().column, 43);
  // So is a missing item, and one too many.
  const ParseError fewer = parse_error(
      "#version 3.7;\nmesh2 { vertex_vectors { 4, <0, 0, 0>, <1, 0, 0>, <0, 1, 0> } face_indices { 1, <0,1,2> } }\n");
  EXPECT_NE(fewer.bare_message().find("declares 4 vectors but lists only 3"), std::string::npos);
  EXPECT_EQ(fewer.location().column, 61);
  const ParseError more = parse_error(
      "#version 3.7;\nmesh2 { vertex_vectors { 2, <0, 0, 0>, <1, 0, 0>, <0, 1, 0> } face_indices { 1, <0,1,2> } }\n");
  EXPECT_NE(more.bare_message().find("declares 2 vectors but lists more"), std::string::npos);
}

TEST(MeshParse, LiteralItemsCountAgainstTheTokenLimit) {
  std::string scene = "#version 3.7;\nmesh {\n";
  for (int i = 0; i < 100; ++i) scene += "triangle { <0, 0, 0>, <1, 0, 0>, <0, 1, " + std::to_string(i + 1) + "> }\n";
  scene += "}\n";
  ParseOptions o;
  o.max_tokens = 1000;   // 100 triangles are 2 600 tokens
  const ParseError e = parse_error(scene, o);
  EXPECT_NE(e.bare_message().find("token limit"), std::string::npos) << e.bare_message();
  o.max_tokens = 3000;
  o.message_sink = [](const std::string&) {};
  EXPECT_EQ(mesh_of(parse_scene_text(scene, "test.pov", o)).data->triangle_count(), 100u);
}

TEST(MeshParse, ReleasedMeshTextStillCountsItsLines) {
  // 20 000 literal triangles (about 1.3 MB of text, released as it is read), then an error two lines later: its
  // line, column and quoted text are the ones of the text as written.
  std::string scene = "#version 3.7;\nmesh {\n";
  for (int i = 0; i < 20000; ++i)
    scene += "triangle { <" + std::to_string(i) + ", 0, 0>, <1, 0, 0>, <0, 1, " + std::to_string(i + 1) + "> }\n";
  scene += "}\n\nsphere { 0, 1 pigment { rgb <1, 0, 0> } bogus }\n";
  const ParseError e = parse_error(scene);
  EXPECT_EQ(e.location().line, 20005);
  EXPECT_EQ(e.location().column, 41);
  EXPECT_NE(std::string(e.what()).find("sphere { 0, 1 pigment { rgb <1, 0, 0> } bogus }"), std::string::npos)
      << e.what();
}

TEST(SourceFile, LinesAreCountedAcrossReleasedRanges) {
  SourceFile f;
  for (int i = 1; i <= 100000; ++i) f.text += "line " + std::to_string(i) + "\n";
  f.release(1000, 300000);
  f.release(200000, 600000);   // overlapping the first: only the rest is released
  EXPECT_EQ(f.line_text(1), "line 1");
  EXPECT_EQ(f.line_text(99999), "line 99999");
  EXPECT_EQ(f.line_text(80000), "line 80000");
  EXPECT_EQ(f.line_text(100), "line 100");
  EXPECT_EQ(f.line_text(100001), "");
  EXPECT_EQ(f.text[500000], '\0');   // dropped pages read back as zeros
}

}  // namespace
}  // namespace povtrace::test
