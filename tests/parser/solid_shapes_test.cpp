// superellipsoid, blob, lathe, prism, sor and height_field in the SDL: parameters as written, POV-Ray's defaults
// and refusals with their positions.
#include <gtest/gtest.h>

#include "parse_helpers.hpp"

namespace povtrace::test {
namespace {

const Object& only_object(const SceneDescription& s) {
  EXPECT_EQ(s.objects.size(), 1u);
  return s.objects.at(0);
}

TEST(SolidShapes, SuperellipsoidExponents) {
  auto s = parse("#version 3.7;\nsuperellipsoid { <0.25, 1.5> translate x }\n");
  auto se = std::get<Superellipsoid>(only_object(s).shape);
  EXPECT_EQ(se.e, 0.25);
  EXPECT_EQ(se.n, 1.5);
  EXPECT_EQ(only_object(s).world_from_object, Matrix::translation({1, 0, 0}));
  s = parse("#version 3.7;\n#declare S = superellipsoid { 0.5 }\nobject { S }\n");   // a float stands for both
  se = std::get<Superellipsoid>(only_object(s).shape);
  EXPECT_EQ(se.e, 0.5);
  EXPECT_EQ(se.n, 0.5);
  const ParseError e = parse_error("#version 3.7;\nsuperellipsoid { <1, 2, 3> }\n");
  EXPECT_EQ(e.location().line, 2);
  EXPECT_EQ(e.location().column, 18);
  EXPECT_NE(e.bare_message().find("expected a 2-D vector"), std::string::npos) << e.bare_message();
}

TEST(SolidShapes, HeightFieldImageAndOptions) {
  auto s = parse("#version 3.7;\nheight_field { png \"hills.png\" gamma 1 smooth water_level 0.25 hierarchy off "
                 "translate y }\n");
  auto h = std::get<HeightField>(only_object(s).shape);
  EXPECT_EQ(h.file, "hills.png");   // not found: kept as written, the renderer reports it
  EXPECT_EQ(h.file_loc.line, 2);
  EXPECT_EQ(h.file_loc.column, 20);
  EXPECT_TRUE(h.smooth);
  EXPECT_EQ(h.water_level, 0.25);
  s = parse("#version 3.7;\nheight_field { \"a.PNG\" }\n");   // the type from the extension
  EXPECT_FALSE(std::get<HeightField>(only_object(s).shape).smooth);
  s = parse("#version 1.0;\nheight_field { png \"a.png\" water_level 64 }\n");   // before 2.0: W / 256
  EXPECT_EQ(std::get<HeightField>(only_object(s).shape).water_level, 0.25);
}

TEST(SolidShapes, HeightFieldsPovtraceDoesNotReadAreRefusedByName) {
  ParseError e = parse_error("#version 3.7;\nheight_field { tga \"a.tga\" smooth }\n");
  EXPECT_NE(e.bare_message().find("a height_field read from a tga image"), std::string::npos) << e.bare_message();
  e = parse_error("#version 3.7;\nheight_field { \"a.gif\" }\n");
  EXPECT_NE(e.bare_message().find("read from a '.gif' image"), std::string::npos) << e.bare_message();
  e = parse_error("#version 3.7;\nheight_field { function 20, 20 { pattern { bozo } } }\n");
  EXPECT_NE(e.bare_message().find("height_field made from"), std::string::npos) << e.bare_message();
  e = parse_error("#version 3.7;\nheight_field { function 1, 20 { x } }\n");
  EXPECT_NE(e.bare_message().find("a size of 2 to 16384 samples"), std::string::npos) << e.bare_message();
  e = parse_error("#version 3.7;\nheight_field { png \"a.png\" gamma 2.2 }\n");
  EXPECT_NE(e.bare_message().find("decoded with a gamma"), std::string::npos) << e.bare_message();
}

// function W, H { F }: POV-Ray's Make_Pattern_Image samples F(j/(W-1), i/(H-1), 0) into a 16-bit grey image (row i
// from the top, the height field's z = H-1-i), unclipped: 1.5 wraps to 1.5·65535 − 65536 = 32766 (in float).
// A pigment function is kept for the renderer to sample.
TEST(SolidShapes, HeightFieldFromAFunction) {
  auto s = parse("#version 3.7;\nheight_field { function 3, 2.4 { x + y * 0.5 } smooth }\n");
  auto h = std::get<HeightField>(only_object(s).shape);
  ASSERT_TRUE(h.samples);
  EXPECT_EQ(h.samples_width, 3);
  EXPECT_EQ(h.samples_depth, 2);
  EXPECT_TRUE(h.smooth);
  const std::vector<std::uint16_t>& v = *h.samples;
  EXPECT_EQ(v[0], 32767);   // z = 0 is the image's bottom row: y = 1, x = 0 → 0.5
  EXPECT_EQ(v[2], 32766);   // x = 1, y = 1 → 1.5, wrapped
  EXPECT_EQ(v[3], 0);       // z = 1: y = 0, x = 0
  EXPECT_EQ(v[5], 65535);   // x = 1, y = 0
  s = parse("#version 3.7;\nheight_field { function 8, 8 { pigment { agate } } }\n");
  h = std::get<HeightField>(only_object(s).shape);
  EXPECT_FALSE(h.samples);
  ASSERT_TRUE(h.pigment_function);
  EXPECT_EQ(h.pigment_function->pattern, PatternKind::agate);
  EXPECT_EQ(h.noise_generator, 2);
}

TEST(SolidShapes, BlobComponents) {
  auto s = parse("#version 3.7;\nblob { threshold 0.6 sphere { <1,0,0>, 2, strength 1.5 translate y scale 2 }\n"
                 "cylinder { 0, x, 0.5, -1 } component 2, 3, <0,0,1> sphere { 0, 1 1 scale <1,2,1> } sturm }\n");
  const auto& b = std::get<Blob>(only_object(s).shape);
  EXPECT_EQ(b.threshold, 0.6);
  EXPECT_TRUE(b.sturm);
  ASSERT_EQ(b.components->size(), 4u);
  const auto& c = *b.components;
  EXPECT_EQ(c[0].kind, BlobComponentKind::sphere);   // translate and a uniform scale keep a sphere
  EXPECT_EQ(c[0].centre, (Vec3{2, 2, 0}));
  EXPECT_EQ(c[0].radius2, 16);
  EXPECT_EQ(c[0].strength, 1.5);
  EXPECT_EQ(c[1].kind, BlobComponentKind::cylinder);
  EXPECT_EQ(c[1].apex, (Vec3{1, 0, 0}));
  EXPECT_EQ(c[1].strength, -1);
  EXPECT_EQ(c[2].strength, 2);   // component strength, radius, centre
  EXPECT_EQ(c[2].radius2, 9);
  EXPECT_EQ(c[2].centre, (Vec3{0, 0, 1}));
  EXPECT_EQ(c[3].kind, BlobComponentKind::ellipsoid);   // a non-uniform scale makes an ellipsoid
  EXPECT_EQ(c[3].transform, Matrix::scaling({1, 2, 1}));
}

// Parse_Ovus: two radii; negative ones are an error; a top radius of twice the bottom one or more gives the sphere it
// equals, with POV-Ray's warning.
TEST(SolidShapes, Ovus) {
  const SceneDescription s = parse("#version 3.7;\novus { 1, 0.6 translate y }\n");
  const auto& o = std::get<Ovus>(s.objects.at(0).shape);
  EXPECT_EQ(o.bottom_radius, 1.0);
  EXPECT_EQ(o.top_radius, 0.6);
  Messages messages;
  const SceneDescription sphere = parse("#version 3.7;\novus { 0.5, 1 }\n", &messages);
  const auto& sp = std::get<Sphere>(sphere.objects.at(0).shape);
  EXPECT_EQ(sp.centre, (Vec3{0, 0.5, 0}));
  EXPECT_EQ(sp.radius, 1.0);
  EXPECT_NE(messages.joined().find("a sphere is used instead"), std::string::npos);
  const ParseError e = parse_error("#version 3.7;\novus { -1, 0.5 }\n");
  EXPECT_NE(e.bare_message().find("both ovus radii must be positive"), std::string::npos) << e.bare_message();
}

TEST(SolidShapes, BlobRefusals) {
  ParseError e = parse_error("#version 3.7;\nblob { cylinder { x, x, 1, 1 } }\n");
  EXPECT_EQ(e.location().column, 8);
  EXPECT_NE(e.bare_message().find("degenerate cylindrical component"), std::string::npos) << e.bare_message();
  e = parse_error("#version 3.7;\nblob { threshold 1 }\n");
  EXPECT_NE(e.bare_message().find("at least one component"), std::string::npos) << e.bare_message();
}

// Parse_Blob_Element_Mods: a component's texture, pigment, normal and finish make its own texture (from a copy of the
// #default texture); transforms after it move it (Transform_Textures), those before do not; the blob's transforms
// move every component texture; components without one keep none (the blob's texture shades them).
TEST(SolidShapes, BlobComponentTextures) {
  const SceneDescription s = parse(
      "#version 3.7;\n#default { finish { ambient 0.3 } }\n"
      "blob { sphere { 0, 1, 1 translate x pigment { bozo } translate y }\n"
      "       sphere { x, 1, 1 }\n"
      "       cylinder { 0, y, 1, 1 texture { pigment { rgb 1 } } texture { pigment { rgbf 0.5 } } }\n"
      "       pigment { rgb 0.5 } translate z }\n");
  const auto& blob = std::get<Blob>(s.objects.at(0).shape);
  ASSERT_EQ(blob.textures.size(), 3u);
  ASSERT_TRUE(blob.textures[0]);
  EXPECT_FALSE(blob.textures[1]);
  ASSERT_TRUE(blob.textures[2]);
  const Texture& first = *blob.textures[0];
  EXPECT_EQ(first.layers.back().finish.ambient.r, static_cast<double>(0.3f));   // from the #default texture
  EXPECT_EQ(first.layers.back().pigment.pattern, PatternKind::bozo);
  // translate y (after the pigment) and the blob's translate z moved the bozo; translate x (before) did not.
  const Vec3 at = first.layers.back().pigment.world_from_pattern.point(Vec3{0, 0, 0});
  EXPECT_EQ(at, (Vec3{0, 1, 1}));
  EXPECT_EQ(blob.textures[2]->layers.size(), 2u);   // two texture blocks stack as layers
  const SceneDescription none = parse("#version 3.7;\nblob { sphere { 0, 1, 1 } pigment { rgb 1 } }\n");
  EXPECT_TRUE(std::get<Blob>(none.objects.at(0).shape).textures.empty());
}

}  // namespace
}  // namespace povtrace::test
