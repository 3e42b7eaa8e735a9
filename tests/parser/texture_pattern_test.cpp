// Patterned textures, uv_mapping and the uv data of meshes in the SDL (POV-Ray 3.7 Parse_Texture, Parse_Tiles,
// Parse_Pattern with TEXTURE_TYPE, Link_Textures; Parse_Object_Mods for uv_mapping; Box::Translate/Scale).
#include <gtest/gtest.h>

#include <fstream>

#include "parse_helpers.hpp"

namespace povtrace::test {
namespace {

SceneDescription scene(const std::string& body) { return parse("#version 3.7;\n" + body); }
const Texture& texture_of(const SceneDescription& s, std::size_t i = 0) { return *s.objects.at(i).texture; }
double single(double d) { return static_cast<double>(static_cast<float>(d)); }

TEST(TexturePatternParse, ListPatternsTakeWholeTextures) {
  const SceneDescription s = scene(
      "#declare T = texture { pigment { rgb 1 } finish { phong 1 } }\n"
      "sphere { 0, 1 texture { checker texture { T } texture { pigment { rgb <1, 0, 0> } } scale 2 } }\n"
      "sphere { 0, 1 texture { hexagon texture { T }, texture { T } } }\n");
  const Texture& t = texture_of(s);
  ASSERT_TRUE(t.patterned());
  EXPECT_TRUE(t.layers.empty());
  EXPECT_EQ(t.pattern->pattern.pattern, PatternKind::checker);
  EXPECT_EQ(t.pattern->pattern.frequency, 0.0);
  EXPECT_EQ(t.pattern->pattern.world_from_pattern.m[0][0], 2);   // the transform moves the pattern only
  ASSERT_EQ(t.pattern->entries.size(), 2u);
  EXPECT_EQ(t.pattern->entries[0].texture->layers.back().finish.phong, 1);
  EXPECT_EQ(t.pattern->entries[1].texture->layers.back().pigment.colour.g, 0);
  EXPECT_EQ(t.pattern->entries[1].value, 1);
  const Texture& h = texture_of(s, 1);
  ASSERT_EQ(h.pattern->entries.size(), 3u);   // the third is the #default texture
  EXPECT_EQ(h.pattern->entries[2].texture->layers.back().finish.phong, 0);
  EXPECT_EQ(h.pattern->entries[2].value, 2);
}

TEST(TexturePatternParse, TextureMapEntriesAndDeclaredMaps) {
  const SceneDescription s = scene(
      "#declare A = texture { pigment { rgb 1 } }\n"
      "#declare M = texture_map { [0.1 A] [0.3, pigment { rgb <0, 1, 0> } finish { ambient 1 }] }\n"
      "sphere { 0, 1 texture { gradient y frequency 2 triangle_wave texture_map { M } translate 1 } }\n"
      "sphere { 0, 1 texture { average texture_map { [A] [3 A] } } }\n");
  const Texture& t = texture_of(s);
  const TexturePattern& p = *t.pattern;
  EXPECT_EQ(p.pattern.pattern, PatternKind::gradient);
  EXPECT_EQ(p.pattern.frequency, 2);
  EXPECT_EQ(p.pattern.wave, WaveType::triangle);
  ASSERT_EQ(p.entries.size(), 2u);
  EXPECT_EQ(p.entries[0].value, single(0.1));
  EXPECT_EQ(p.entries[1].value, single(0.3));
  EXPECT_EQ(p.entries[1].texture->layers.back().finish.ambient.r, 1);
  EXPECT_EQ(p.entries[1].texture->layers.back().pigment.colour.g, 1);
  const TexturePattern& a = *texture_of(s, 1).pattern;
  EXPECT_EQ(a.pattern.pattern, PatternKind::average);
  EXPECT_EQ(a.entries[0].value, 1);   // an average's weight may be left out
  EXPECT_EQ(a.entries[1].value, 3);
}

TEST(TexturePatternParse, TilesUvMappingAndDeclaredPatternedTextures) {
  const SceneDescription s = scene(
      "#declare A = texture { pigment { rgb 1 } }\n"
      "#declare B = texture { pigment { rgb 0 } }\n"
      "#declare P = texture { tiles { texture { A } tile2 texture { B } } }\n"
      "sphere { 0, 1 texture { P scale 3 } }\n"
      "sphere { 0, 1 texture { uv_mapping pigment { rgb <1, 0, 0> } finish { phong 1 } } }\n");
  const TexturePattern& p = *texture_of(s).pattern;
  EXPECT_EQ(p.pattern.pattern, PatternKind::checker);
  EXPECT_EQ(p.entries[0].texture->layers.back().pigment.colour.r, 0);   // tile2 is the even square
  EXPECT_EQ(p.entries[1].texture->layers.back().pigment.colour.r, 1);
  EXPECT_EQ(p.pattern.world_from_pattern.m[1][1], 3);
  const TexturePattern& uv = *texture_of(s, 1).pattern;
  EXPECT_EQ(uv.pattern.pattern, PatternKind::uv_mapping);
  ASSERT_EQ(uv.entries.size(), 1u);
  EXPECT_EQ(uv.entries[0].texture->layers.back().finish.phong, 1);
}

TEST(TexturePatternParse, ErrorsAndRefusals) {
  const std::string t = "#declare T = texture { pigment { rgb 1 } }\n";
  ParseError e = parse_error("#version 3.7;\nsphere { 0, 1 texture { gradient x } }\n");
  EXPECT_EQ(e.location().column, 25);
  EXPECT_NE(e.bare_message().find("patterned texture must have texture_map"), std::string::npos) << e.what();
  e = parse_error("#version 3.7;\n" + t + "sphere { 0, 1 texture { checker texture { T } } texture { T } }\n");
  EXPECT_NE(e.bare_message().find("cannot layer over a patterned texture"), std::string::npos) << e.what();
  e = parse_error("#version 3.7;\n" + t + "sphere { 0, 1 texture { T } texture { checker texture { T } } }\n");
  EXPECT_NE(e.bare_message().find("cannot layer a patterned texture over another"), std::string::npos) << e.what();
  e = parse_error("#version 3.7;\n" + t + "sphere { 0, 1 texture { checker texture { T } } pigment { rgb 1 } }\n");
  EXPECT_NE(e.bare_message().find("cannot layer over a patterned texture"), std::string::npos) << e.what();
  e = parse_error("#version 3.7;\n" + t + "sphere { 0, 1 texture { checker texture { T } texture_map { [0 T] } } }\n");
  EXPECT_NE(e.bare_message().find("texture_map cannot be used with this pattern type"), std::string::npos);
  e = parse_error("#version 3.7;\n" + t + "sphere { 0, 1 texture { bozo color_map { [0 rgb 1] } } }\n");
  EXPECT_NE(e.bare_message().find("'color_map' can only be used in a pigment"), std::string::npos) << e.what();
  e = parse_error("#version 3.7;\n" + t + "sphere { 0, 1 texture { material_map { png \"x.png\" texture { T } } } }\n");
  EXPECT_NE(e.bare_message().find("cannot open the image file 'x.png'"), std::string::npos) << e.what();
  e = parse_error("#version 3.7;\n" + t + "sphere { 0, 1 texture { material_map { png \"povmap.png\" } } }\n");
  EXPECT_NE(e.bare_message().find("a material_map needs at least one texture"), std::string::npos) << e.what();
  e = parse_error("#version 3.7;\n" + t + "#declare P = texture { checker texture { T } }\n"
                  "sphere { 0, 1 texture { P pigment { rgb 1 } } }\n");
  EXPECT_NE(e.bare_message().find("a transform"), std::string::npos) << e.what();
  e = parse_error("#version 3.7;\n" + t + "#default { texture { checker texture { T } } }\n");
  EXPECT_NE(e.bare_message().find("a patterned #default texture"), std::string::npos) << e.what();
}

TEST(UvMappingParse, ObjectFlagKeepsTexturesFromLaterTransforms) {
  const SceneDescription s = scene(
      "sphere { 0, 1 uv_mapping pigment { checker } scale 2 }\n"
      "union { sphere { 0, 1 } sphere { 1, 1 texture { pigment { rgb 1 } } } uv_mapping pigment { rgb 0 } }\n");
  const Object& o = s.objects.at(0);
  EXPECT_TRUE(o.uv_mapping);
  EXPECT_EQ(o.texture->layers.back().pigment.world_from_pattern.m[0][0], 1);   // not scaled with the sphere
  EXPECT_EQ(o.world_from_object.m[0][0], 2);
  const Csg& u = std::get<Csg>(s.objects.at(1).shape);
  EXPECT_TRUE(u.children[0].uv_mapping);    // inherits the texture, and the flag with it
  EXPECT_FALSE(u.children[1].uv_mapping);   // keeps its own texture
  ParseError e = parse_error("#version 3.7;\nsphere { 0, 1 pigment { rgb 1 } uv_mapping }\n");
  EXPECT_EQ(e.location().column, 33);
  EXPECT_NE(e.bare_message().find("uv_mapping must be specified before texture"), std::string::npos) << e.what();
}

TEST(UvMappingParse, NormalUvMappingAndBumpMap) {
  ScratchFolder folder;
  WorkingDirectory cwd(folder.path());
  std::ofstream(folder / "b.png") << "x";
  const SceneDescription s = scene(
      "sphere { 0, 1 normal { uv_mapping gradient x 0.3 scale 0.1 } }\n"
      "sphere { 0, 1 normal { bump_map { png \"b.png\" bump_size 2 interpolate 2 use_index map_type 7 } } }\n");
  const Normal& n = *s.objects.at(0).texture->layers.back().normal;
  EXPECT_EQ(n.kind, NormalKind::uv_mapping);
  ASSERT_TRUE(n.uv_normal);
  EXPECT_EQ(n.uv_normal->amount, 0.3);
  EXPECT_EQ(n.uv_normal->pattern.world_from_pattern.m[0][0], 0.1);
  const Normal& b = *s.objects.at(1).texture->layers.back().normal;
  EXPECT_EQ(b.kind, NormalKind::bump_map);
  EXPECT_EQ(b.amount, 2);
  ASSERT_TRUE(b.pattern.image);
  EXPECT_TRUE(b.pattern.image->use_index);
  EXPECT_EQ(b.pattern.image->map_type, 7);   // bump maps take any map type (unknown ones map planar)
  EXPECT_EQ(b.pattern.image->gamma.mode, ImageGammaMode::none);   // bump maps are read without gamma handling
}

TEST(UvMappingParse, MeshUvVectorsAreKept) {
  const SceneDescription s = scene(
      "mesh { triangle { <0, 0, 0>, <1, 0, 0>, <0, 1, 0> } triangle { <1, 0, 0>, <1, 1, 0>, <0, 1, 0>\n"
      "  uv_vectors <1, 0>, <1, 1>, <0, 1> } }\n"
      "mesh2 { vertex_vectors { 3, <0, 0, 0>, <1, 0, 0>, <0, 1, 0> } uv_vectors { 2, <0.5, 0.5>, <1, 0> }\n"
      "  face_indices { 1, <0, 1, 2> } uv_indices { 1, <1, 0, 1> } }\n");
  const MeshData& m = *std::get<Mesh>(s.objects.at(0).shape).data;
  ASSERT_EQ(m.face_uvs.size(), 6u);
  EXPECT_EQ(m.face_uvs[0], 0u);   // the first triangle has none: <0, 0>
  EXPECT_EQ(m.uvs[0], 0.0);
  EXPECT_EQ(m.uvs[2 * m.face_uvs[4]], 1.0);       // second triangle, second corner <1, 1>
  EXPECT_EQ(m.uvs[2 * m.face_uvs[4] + 1], 1.0);
  const MeshData& m2 = *std::get<Mesh>(s.objects.at(1).shape).data;
  EXPECT_EQ(m2.face_uvs, (std::vector<std::uint32_t>{1, 0, 1}));
  EXPECT_EQ(m2.uvs, (std::vector<double>{0.5, 0.5, 1, 0}));
}

TEST(BoxParse, TranslationsAndScalingsMoveTheCornersUntilARotation) {
  const SceneDescription s = scene(
      "box { <0, 0, 0>, <1, 2, 3> scale <-2, 1, 1> translate x }\n"
      "box { <0, 0, 0>, <1, 1, 1> rotate y * 90 scale -1 }\n");
  const Box& a = std::get<Box>(s.objects.at(0).shape);
  EXPECT_EQ(a.corner1.x, -1);   // scaled to −2 … 0 (re-sorted), then moved by 1
  EXPECT_EQ(a.corner2.x, 1);
  EXPECT_EQ(a.corner2.z, 3);
  EXPECT_FALSE(a.rotated);
  EXPECT_EQ(s.objects.at(0).world_from_object, Matrix::identity());
  const Box& b = std::get<Box>(s.objects.at(1).shape);
  EXPECT_TRUE(b.rotated);
  EXPECT_EQ(b.corner2.x, 1);    // from the rotation on, transforms go into the matrix
  EXPECT_EQ(s.objects.at(1).world_from_object.m[1][1], -1);
}

TEST(TexturePatterns, MaterialMapKeepsItsImageAndTexturesInOrder) {
  const SceneDescription sd = parse(
      "#version 3.7;\nglobal_settings { assumed_gamma 1 }\n"
      "sphere { 0, 1 texture { material_map { png \"povmap.png\" once map_type 1 interpolate 2 repeat <2, 3>\n"
      "  texture { pigment { rgb 1 } } texture { pigment { rgb <1, 0, 0> } } texture { pigment { rgb 0 } } }\n"
      "  scale 2 } }\n");
  const Texture& tex = *sd.objects.at(0).texture;
  ASSERT_TRUE(tex.patterned());
  EXPECT_FALSE(tex.unsupported);
  const TexturePattern& p = *tex.pattern;
  EXPECT_EQ(p.pattern.pattern, PatternKind::material_map);
  ASSERT_TRUE(p.pattern.image);
  EXPECT_TRUE(p.pattern.image->once);
  EXPECT_EQ(p.pattern.image->map_type, 1);
  EXPECT_EQ(p.pattern.image->interpolate, 2);
  EXPECT_EQ(p.pattern.image->repeat_u, 2.0);
  EXPECT_EQ(p.pattern.image->gamma.mode, ImageGammaMode::none);   // read raw, as POV-Ray reads bump maps
  ASSERT_EQ(p.entries.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) EXPECT_EQ(p.entries[i].value, static_cast<double>(i));
  EXPECT_EQ(p.pattern.world_from_pattern.point({1, 1, 1}), (Vec3{2, 2, 2}));   // the texture's transforms move it
}

}  // namespace
}  // namespace povtrace::test
