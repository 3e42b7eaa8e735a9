// What the parser puts in the SceneDescription for small scenes: camera (POV-Ray's fixed order of application,
// povray-pixel-pipeline.md §1), lights (§3), shapes and transforms (povray-sdl-and-geometry.md §8–§9), textures
// and finishes (§11, pipeline §2), #default, object copies, global settings and background.
#include <array>
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "parse_helpers.hpp"
#include "parser/extents/object_notes.hpp"
#include "scene/description_transforms.hpp"

namespace povtrace::test {
namespace {

constexpr double kTol = 1e-12;

void expect_vec_near(Vec3 got, Vec3 want, double tol = kTol) {
  EXPECT_NEAR(got.x, want.x, tol) << "x";
  EXPECT_NEAR(got.y, want.y, tol) << "y";
  EXPECT_NEAR(got.z, want.z, tol) << "z";
}

// Colours are stored in single precision, as POV-Ray stores them: compare with the float-rounded value.
double single(double v) { return static_cast<float>(v); }
void expect_colour(const Colour& got, const Colour& want) {
  EXPECT_NEAR(got.r, single(want.r), kTol) << "r";
  EXPECT_NEAR(got.g, single(want.g), kTol) << "g";
  EXPECT_NEAR(got.b, single(want.b), kTol) << "b";
  EXPECT_NEAR(got.f, single(want.f), kTol) << "f";
  EXPECT_NEAR(got.t, single(want.t), kTol) << "t";
}

void expect_matrix_near(const Matrix& a, const Matrix& b) {
  for (std::size_t i = 0; i < 4; ++i)
    for (std::size_t j = 0; j < 3; ++j) EXPECT_NEAR(a.m[i][j], b.m[i][j], kTol) << "row " << i << " column " << j;
}

SceneDescription scene(const std::string& body) { return parse("#version 3.7;\n" + body); }

Camera camera_of(const std::string& camera_block) { return scene(camera_block).camera; }

const TextureLayer& top_layer(const Object& o) {
  EXPECT_TRUE(o.texture);
  return o.texture->layers.back();
}

// ---- Camera -------------------------------------------------------------------------------------------------------
TEST(Camera, DefaultsWithoutACameraAndWithAnEmptyOne) {
  for (const Camera& c : {scene("").camera, camera_of("camera { }")}) {
    EXPECT_EQ(c.projection, Projection::perspective);
    expect_vec_near(c.location, {0, 0, 0});
    expect_vec_near(c.direction, {0, 0, 1});   // |D| = 1: `angle` is only applied when written
    expect_vec_near(c.up, {0, 1, 0});
    expect_vec_near(c.right, {1.33, 0, 0});    // 1.33, not 4/3
  }
}

TEST(Camera, AngleIsAppliedAfterDirectionWhateverTheOrder) {
  // |D| = |R| / (2 tan(a/2)) = 1.33 / 2 for 90°, along the normalised direction.
  for (const char* block : {"camera { angle 90 direction <0,0,5> }", "camera { direction <0,0,5> angle 90 }"}) {
    const Camera c = camera_of(block);
    expect_vec_near(c.direction, {0, 0, 0.665}, 1e-12);
    expect_vec_near(c.right, {1.33, 0, 0});
  }
  const Camera wide = camera_of("camera { right x*2 angle 90 }");
  expect_vec_near(wide.direction, {0, 0, 1}, 1e-12);
}

TEST(Camera, LookAtKeepsTheLengthsAndTheHandedness) {
  const Camera c = camera_of(
      "camera { location <0,0,-5> direction <0,0,2> up <0,3,0> right <4,0,0> look_at <1,1,0> }");
  const Vec3 d = normalize(Vec3{1, 1, 5});
  const Vec3 r = normalize(cross(Vec3{0, 1, 0}, d));
  const Vec3 u = cross(d, r);
  expect_vec_near(c.location, {0, 0, -5});
  expect_vec_near(c.direction, d * 2);
  expect_vec_near(c.right, r * 4);
  expect_vec_near(c.up, u * 3);
  EXPECT_NEAR(length(c.direction), 2, kTol);
  EXPECT_GT(dot(cross(c.up, c.direction), c.right), 0);   // still left-handed
}

TEST(Camera, LookAtOrderDoesNotMatter) {
  const Camera a = camera_of("camera { look_at <1,0,1> location <0,1,0> }");
  const Camera b = camera_of("camera { location <0,1,0> look_at <1,0,1> }");
  expect_vec_near(a.direction, b.direction);
  expect_vec_near(a.right, b.right);
  expect_vec_near(a.up, b.up);
}

TEST(Camera, SkySetsTheRoll) {
  const Camera c = camera_of("camera { sky x look_at <0,0,1> }");
  // R̂ = sky × D̂ = x × z = -y; Û = D̂ × R̂ = z × -y = x.
  expect_vec_near(c.right, {0, -1.33, 0});
  expect_vec_near(c.up, {1, 0, 0});
}

TEST(Camera, NegativeRightMirrors) {
  const Camera plain = camera_of("camera { right -x*1.33 }");
  expect_vec_near(plain.right, {-1.33, 0, 0});
  // With look_at the handedness sign of the written vectors survives: right points the other way.
  const Camera c = camera_of("camera { right -x*1.33 look_at <1,0,1> }");
  const Vec3 d = normalize(Vec3{1, 0, 1});
  const Vec3 r = normalize(cross(Vec3{0, 1, 0}, d));
  expect_vec_near(c.right, r * -1.33);
  EXPECT_LT(dot(cross(c.up, c.direction), c.right), 0);
  const Camera normal = camera_of("camera { look_at <1,0,1> }");
  expect_vec_near(normal.right, r * 1.33);
}

TEST(Camera, OrthographicResize) {
  // Neither up nor right given: R and U scale by |look_at - location| / |D|.
  const Camera o = camera_of("camera { orthographic location <0,0,-10> look_at 0 }");
  EXPECT_EQ(o.projection, Projection::orthographic);
  expect_vec_near(o.right, {13.3, 0, 0}, 1e-12);
  expect_vec_near(o.up, {0, 10, 0}, 1e-12);
  // With an angle the view is 2 d tan(a/2) wide.
  const Camera a = camera_of("camera { orthographic location <0,0,-10> look_at 0 angle 60 }");
  EXPECT_NEAR(length(a.right), 20 * std::tan(M_PI / 6), 1e-12);
  EXPECT_NEAR(length(a.up), 20 * std::tan(M_PI / 6) / 1.33, 1e-12);
  // Explicit up and right, no angle: the rectangle is used as given.
  const Camera e = camera_of("camera { orthographic location <0,0,-10> look_at 0 up y*2 right x*4 }");
  expect_vec_near(e.right, {4, 0, 0});
  expect_vec_near(e.up, {0, 2, 0});
  // Without look_at the distance is measured to the default look_at <0,0,1>.
  const Camera d = camera_of("camera { orthographic location <0,0,-4> }");
  expect_vec_near(d.right, {1.33 * 5, 0, 0}, 1e-12);
}

TEST(Camera, OwnTransformsAreAppliedLast) {
  const Camera t = camera_of("camera { translate <1,0,0> location <0,0,-5> look_at <0,0,0> }");
  expect_vec_near(t.location, {1, 0, -5});
  expect_vec_near(t.direction, {0, 0, 1});   // look_at was resolved before the translate
  // rotate y*90 takes +z to +x and the location <0,0,-5> to <-5,0,0>.
  const Camera r = camera_of("camera { location <0,0,-5> look_at 0 rotate y*90 }");
  expect_vec_near(r.location, {-5, 0, 0}, 1e-12);
  expect_vec_near(r.direction, {1, 0, 0}, 1e-12);
  expect_vec_near(r.right, {0, 0, -1.33}, 1e-12);
  expect_vec_near(r.up, {0, 1, 0}, 1e-12);
}

TEST(Camera, DeclaredCameraIsCopiedAndTheLastCameraWins) {
  const SceneDescription s = scene(
      "#declare C = camera { location <0,0,-3> }\n"
      "camera { location <9,9,9> }\n"
      "camera { C }\n");
  expect_vec_near(s.camera.location, {0, 0, -3});
}

// ---- Lights ------------------------------------------------------------------------------------------------------
TEST(Lights, PointLightDefaults) {
  const SceneDescription s = scene("light_source { <1,2,3> color rgb <1,0.5,0.25> }\n");
  ASSERT_EQ(s.lights.size(), 1u);
  const Light& l = s.lights[0];
  expect_vec_near(l.location, {1, 2, 3});
  expect_colour(l.colour, {1, 0.5, 0.25, 0, 0});
  EXPECT_FALSE(l.spotlight);
  EXPECT_FALSE(l.parallel);
  EXPECT_FALSE(l.shadowless);
  EXPECT_EQ(l.fade_distance, 0);
  EXPECT_EQ(l.fade_power, 0);
  EXPECT_EQ(l.loc.line, 2);
  EXPECT_EQ(l.loc.column, 1);
}

TEST(Lights, SpotlightDefaultsAndValues) {
  const SceneDescription s = scene(
      "light_source { <0,10,0> rgb 1 spotlight point_at <0,0,0> }\n"
      "light_source { <0,10,0>, rgb 1 spotlight radius 10 falloff 25 tightness 5 }\n");
  ASSERT_EQ(s.lights.size(), 2u);
  EXPECT_TRUE(s.lights[0].spotlight);
  EXPECT_EQ(s.lights[0].radius, 30);
  EXPECT_EQ(s.lights[0].falloff, 45);
  EXPECT_EQ(s.lights[0].tightness, 0);
  expect_vec_near(s.lights[0].point_at, {0, 0, 0});
  EXPECT_EQ(s.lights[1].radius, 10);
  EXPECT_EQ(s.lights[1].falloff, 25);
  EXPECT_EQ(s.lights[1].tightness, 5);
  expect_vec_near(s.lights[1].point_at, {0, 0, 1});   // default point_at
}

TEST(Lights, ParallelShadowlessFade) {
  const SceneDescription s = scene(
      "light_source { <0,10,0> color rgb 1 parallel point_at 0 }\n"
      "light_source { <0,10,0> color rgb 0.5 shadowless fade_distance 5 fade_power 2 }\n");
  ASSERT_EQ(s.lights.size(), 2u);
  EXPECT_TRUE(s.lights[0].parallel);
  EXPECT_FALSE(s.lights[0].shadowless);
  EXPECT_TRUE(s.lights[1].shadowless);
  EXPECT_EQ(s.lights[1].fade_distance, 5);
  EXPECT_EQ(s.lights[1].fade_power, 2);
  expect_colour(s.lights[1].colour, {0.5, 0.5, 0.5, 0, 0});
}

TEST(Lights, TransformsMoveLocationAndPointAt) {
  const SceneDescription s = scene(
      "#declare L = light_source { <1,0,0> rgb 1 spotlight point_at <1,-1,0> }\n"
      "light_source { L translate y }\n"
      "object { L rotate y*90 }\n");
  ASSERT_EQ(s.lights.size(), 2u);
  expect_vec_near(s.lights[0].location, {1, 1, 0});
  expect_vec_near(s.lights[0].point_at, {1, 0, 0});
  EXPECT_TRUE(s.lights[0].spotlight);
  expect_vec_near(s.lights[1].location, {0, 0, -1}, 1e-12);
  expect_vec_near(s.lights[1].point_at, {0, -1, -1}, 1e-12);
}

// ---- Shapes ---------------------------------------------------------------------------------------------------
TEST(Shapes, SpherePlaneBox) {
  const SceneDescription s = scene(
      "sphere { <1,2,3>, 4 }\n"
      "plane { <0,2,0>, 3 }\n"
      "plane { <3,0,4>, -1 }\n"
      "box { <1,-1,2>, <-1,1,-2> }\n");
  ASSERT_EQ(s.objects.size(), 4u);
  const auto& sphere = std::get<Sphere>(s.objects[0].shape);
  expect_vec_near(sphere.centre, {1, 2, 3});
  EXPECT_EQ(sphere.radius, 4);
  // The normal is normalised first; the distance is along the unit normal (not divided by |N|).
  const auto& p1 = std::get<Plane>(s.objects[1].shape);
  expect_vec_near(p1.normal, {0, 1, 0});
  EXPECT_EQ(p1.distance, 3);
  const auto& p2 = std::get<Plane>(s.objects[2].shape);
  expect_vec_near(p2.normal, {0.6, 0, 0.8});
  EXPECT_EQ(p2.distance, -1);
  const auto& b = std::get<Box>(s.objects[3].shape);
  expect_vec_near(b.corner1, {-1, -1, -2});
  expect_vec_near(b.corner2, {1, 1, 2});
  for (const Object& o : s.objects) {
    EXPECT_FALSE(o.inverse);
    EXPECT_FALSE(o.no_shadow);
    EXPECT_FALSE(o.interior.has_value());
    expect_matrix_near(o.world_from_object, Matrix::identity());
  }
  EXPECT_EQ(s.objects[3].loc.line, 5);
}

// no_image, no_reflection, no_radiosity [bool] (POV-Ray's Bool_Flag): on by default, a value > 0 sets, <= 0 clears
// (also a flag the declared object had).
TEST(Shapes, RayFlagsTakeAnOptionalBool) {
  const SceneDescription s = scene(
      "#declare S = sphere { 0, 1 no_image no_reflection no_radiosity }\n"
      "sphere { 0, 1 no_image no_reflection no_radiosity }\n"
      "sphere { 0, 1 no_image 0 no_reflection off no_radiosity false }\n"
      "object { S no_image 0 }\n"
      "object { S no_reflection -1 no_radiosity 0 }\n"
      "sphere { 0, 1 no_image on no_reflection 0.5 }\n"
      "sphere { 0, 1 }\n");
  ASSERT_EQ(s.objects.size(), 6u);
  auto flags = [&](std::size_t i) {
    const Object& o = s.objects[i];
    EXPECT_FALSE(o.unsupported) << i;
    return std::array<bool, 3>{o.no_image, o.no_reflection, o.no_radiosity};
  };
  EXPECT_EQ(flags(0), (std::array<bool, 3>{true, true, true}));
  EXPECT_EQ(flags(1), (std::array<bool, 3>{false, false, false}));
  EXPECT_EQ(flags(2), (std::array<bool, 3>{false, true, true}));
  EXPECT_EQ(flags(3), (std::array<bool, 3>{true, false, false}));
  EXPECT_EQ(flags(4), (std::array<bool, 3>{true, true, false}));
  EXPECT_EQ(flags(5), (std::array<bool, 3>{false, false, false}));
}

// A disc's optional hole radius stops at these modifiers (they start no number).
TEST(Shapes, RayFlagsAfterADisc) {
  const SceneDescription s = scene("disc { 0, y, 1 no_image }\ndisc { 0, y, 1 no_reflection 0 }\n");
  ASSERT_EQ(s.objects.size(), 2u);
  EXPECT_TRUE(s.objects[0].no_image);
  EXPECT_FALSE(s.objects[1].no_reflection);
}

TEST(Shapes, ObjectFlagsAndInterior) {
  const SceneDescription s = scene(
      "sphere { 0, 1 no_shadow inverse hollow interior { ior 1.5 } }\n"
      "sphere { 0, 1 inverse inverse hollow on }\n");
  ASSERT_EQ(s.objects.size(), 2u);
  EXPECT_TRUE(s.objects[0].no_shadow);
  EXPECT_TRUE(s.objects[0].inverse);
  ASSERT_TRUE(s.objects[0].interior.has_value());
  EXPECT_EQ(s.objects[0].interior->ior, 1.5);
  EXPECT_FALSE(s.objects[1].inverse);
}

// ---- Transforms ----------------------------------------------------------------------------------------------
TEST(Transforms, ComposeInWrittenOrder) {
  const SceneDescription s = scene(
      "sphere { 0, 1 translate x rotate y*90 }\n"
      "sphere { 0, 1 rotate y*90 translate x }\n"
      "sphere { 0, 1 scale 2 translate <1,2,3> }\n"
      "sphere { 0, 1 translate <1,2,3> scale 2 }\n");
  ASSERT_EQ(s.objects.size(), 4u);
  // Row vectors: the total is M1·M2·…; rotate y*90 takes +x to -z.
  expect_vec_near(s.objects[0].world_from_object.point({0, 0, 0}), {0, 0, -1}, 1e-12);
  expect_vec_near(s.objects[1].world_from_object.point({0, 0, 0}), {1, 0, 0}, 1e-12);
  expect_vec_near(s.objects[1].world_from_object.point({1, 0, 0}), {1, 0, -1}, 1e-12);
  expect_vec_near(s.objects[2].world_from_object.point({1, 1, 1}), {3, 4, 5});
  expect_vec_near(s.objects[3].world_from_object.point({1, 1, 1}), {4, 6, 8});
}

TEST(Transforms, RotateMatrixTransformBlockAndScaleZero) {
  Messages m;
  const SceneDescription s = parse(
      "#version 3.7;\n"
      "sphere { 0, 1 rotate <90,0,90> }\n"
      "sphere { 0, 1 matrix <1,0,0, 0,1,0, 0,0,1, 1,2,3> }\n"
      "sphere { 0, 1 transform { translate x scale 2 inverse } }\n"
      "sphere { 0, 1 scale <2,0,1> }\n",
      &m);
  ASSERT_EQ(s.objects.size(), 4u);
  expect_vec_near(s.objects[0].world_from_object.vector({0, 1, 0}), {0, 0, 1}, 1e-12);   // about x, then z
  expect_vec_near(s.objects[1].world_from_object.point({0, 0, 0}), {1, 2, 3});
  // The inverse of "translate x then scale 2" maps <2,0,0> back to <0,0,0>.
  expect_vec_near(s.objects[2].world_from_object.point({2, 0, 0}), {0, 0, 0});
  // scale 0 in an axis becomes 1 there, with a warning.
  expect_matrix_near(s.objects[3].world_from_object, Matrix::scaling({2, 1, 1}));
  ASSERT_EQ(m.items.size(), 1u);
  EXPECT_NE(m.items[0].find("test.pov:5:15: warning: scale by 0"), std::string::npos) << m.items[0];
}

// POV-Ray's Sphere::Translate, Rotate and uniform Scale keep a sphere a sphere; a non-uniform scale, a matrix or a
// transform block make it an ellipsoid for good (what --povray-tolerances folds, renderer/scene_scale.hpp).
TEST(Transforms, SphereBecomesAnEllipsoidAsInPovray) {
  const SceneDescription s = scene(
      "sphere { 0, 1 translate x rotate y*30 scale 2 scale -3 }\n"
      "sphere { 0, 1 scale <1,2,1> scale <1,0.5,1> }\n"
      "sphere { 0, 1 matrix <1,0,0, 0,1,0, 0,0,1, 0,0,0> }\n"
      "sphere { 0, 1 transform { translate x } }\n"
      "union { sphere { 0, 1 } sphere { x, 1 scale <1,2,1> } scale 2 }\n");
  ASSERT_EQ(s.objects.size(), 5u);
  EXPECT_FALSE(std::get<Sphere>(s.objects[0].shape).ellipsoid);
  EXPECT_TRUE(std::get<Sphere>(s.objects[1].shape).ellipsoid);   // even though the scales cancel
  EXPECT_TRUE(std::get<Sphere>(s.objects[2].shape).ellipsoid);
  EXPECT_TRUE(std::get<Sphere>(s.objects[3].shape).ellipsoid);
  const Csg& u = std::get<Csg>(s.objects[4].shape);
  EXPECT_FALSE(std::get<Sphere>(u.children.at(0).shape).ellipsoid);
  EXPECT_TRUE(std::get<Sphere>(u.children.at(1).shape).ellipsoid);
}

// POV-Ray's Parse_Camera: |look_at − location|² < 1e-10 is an error, an absolute test; with POV-Ray's tolerances
// povtrace gives the same error (a camera 1e-6 times the usual size), without them it renders the scene.
TEST(Camera, LookAtTooCloseToTheLocationIsPovraysErrorWithItsTolerances) {
  const std::string text = "#version 3.7;\ncamera { location <0, 0, -7e-6> look_at <0, 1e-6, 0> }\n";
  ParseOptions povray;
  povray.povray_tolerances = true;
  const ParseError e = parse_error(text, povray);
  EXPECT_NE(std::string(e.what()).find("test.pov:2:33: error: Camera location and look_at point must be different."),
            std::string::npos) << e.what();
  EXPECT_NO_THROW(parse(text));
  EXPECT_NO_THROW(parse_scene_text("#version 3.7;\ncamera { location <0, 0, -2e-5> look_at <0, 0, 0> }\n", "test.pov",
                                   povray));   // 4e-10: allowed
}

// POV-Ray 3.7 renders these: angle 0 is no angle for a perspective camera (a warning says so); an orthographic
// camera's angle may have no value, meaning 0, and any angle asks for the resize even with up and right given.
TEST(Camera, AngleZeroIsNoAngleForAPerspectiveCameraAndWarns) {
  Messages m;
  const Camera c = parse("#version 3.7;\ncamera { location -5*z angle 0 }\n", &m).camera;
  const Camera plain = camera_of("camera { location -5*z }");
  expect_vec_near(c.direction, plain.direction);
  expect_vec_near(c.right, plain.right);
  ASSERT_EQ(m.items.size(), 1u);
  EXPECT_EQ(m.items[0], "test.pov:2:1: warning: a perspective camera's angle 0 leaves its field of view as it is "
                        "(POV-Ray ignores it)\ncamera { location -5*z angle 0 }\n^");
}

TEST(Camera, OrthographicAngleWithoutAValueIsZeroAndResizes) {
  const Camera none = camera_of("camera { orthographic location <0,0,-10> look_at 0 up y*2 right x*4 angle }");
  const Camera zero = camera_of("camera { orthographic location <0,0,-10> look_at 0 up y*2 right x*4 angle 0 }");
  // |look_at − location| / |D| = 10: the given rectangle scaled as POV-Ray does when an angle is written.
  expect_vec_near(none.right, {40, 0, 0}, 1e-12);
  expect_vec_near(none.up, {0, 20, 0}, 1e-12);
  expect_vec_near(zero.right, none.right);
  expect_vec_near(zero.up, none.up);
}

TEST(Camera, ProjectionKeywordsAtTheStartTheLastOneCounts) {
  EXPECT_EQ(camera_of("camera { perspective orthographic location -5*z }").projection, Projection::orthographic);
  // Before 3.5 POV-Ray took the keywords anywhere.
  EXPECT_EQ(parse("#version 3.1;\ncamera { location -5*z orthographic }\n").camera.projection,
            Projection::orthographic);
}

// povtrace refuses a look_at at the location at any scale, by exact equality, but (unlike POV-Ray's absolute test)
// not a camera that is merely small.
TEST(Camera, LookAtAtTheLocationIsAnErrorAtEveryScaleAndATinyCameraIsNot) {
  for (const char* v : {"<1e-7, 2e-7, -3e-7>", "<1e7, 2e7, -3e7>", "<1e-200, 0, 0>"}) {
    const ParseError e = parse_error(std::string("#version 3.7;\ncamera { location ") + v + " look_at " + v + " }\n");
    EXPECT_NE(e.bare_message().find("Camera location and look_at point must be different."), std::string::npos) << v;
  }
  const Camera tiny = camera_of("camera { location <0, 0, -5e-7> look_at 0 }");
  EXPECT_NEAR(length(tiny.direction), 1.0, 1e-12);
}

// ---- Textures -------------------------------------------------------------------------------------------------
TEST(Textures, DefaultTextureAndFinishDefaults) {
  const SceneDescription s = scene("sphere { 0, 1 }\n");
  ASSERT_EQ(s.objects.size(), 1u);
  ASSERT_EQ(s.objects[0].texture->layers.size(), 1u);
  const TextureLayer& l = top_layer(s.objects[0]);
  EXPECT_EQ(l.pigment.pattern, PatternKind::solid);
  expect_colour(l.pigment.colour, {0, 0, 0, 0, 0});
  const Finish& f = l.finish;
  expect_colour(f.ambient, {0.1, 0.1, 0.1, 0, 0});
  expect_colour(f.emission, {0, 0, 0, 0, 0});
  EXPECT_EQ(f.diffuse, 0.6);
  EXPECT_EQ(f.diffuse_back, 0);
  EXPECT_EQ(f.brilliance, 1);
  EXPECT_EQ(f.phong, 0);
  EXPECT_EQ(f.phong_size, 40);
  EXPECT_EQ(f.specular, 0);
  EXPECT_EQ(f.roughness, 0.05);
  EXPECT_EQ(f.metallic, 0);
}

struct FinishCase {
  std::string finish;
  double Finish::*field;
  double expected;
};

class FinishValue : public ::testing::TestWithParam<FinishCase> {};

TEST_P(FinishValue, IsStored) {
  const SceneDescription s = scene("sphere { 0, 1 finish { " + GetParam().finish + " } }\n");
  ASSERT_EQ(s.objects.size(), 1u);
  EXPECT_DOUBLE_EQ(top_layer(s.objects[0]).finish.*(GetParam().field), GetParam().expected) << GetParam().finish;
}

INSTANTIATE_TEST_SUITE_P(
    Table, FinishValue,
    ::testing::Values(FinishCase{"metallic", &Finish::metallic, 1}, FinishCase{"metallic 0.3", &Finish::metallic, 0.3},
                      FinishCase{"metallic phong 1", &Finish::metallic, 1},
                      FinishCase{"metallic off", &Finish::metallic, 0}, FinishCase{"metallic on", &Finish::metallic, 1},
                      FinishCase{"metallic abs(-0.5)", &Finish::metallic, 0.5},
                      FinishCase{"metallic phong 1", &Finish::phong, 1},
                      FinishCase{"phong 0.5", &Finish::phong_size, 40},   // the rest keeps its default
                      FinishCase{"phong 1 phong_size 200", &Finish::phong_size, 200},
                      FinishCase{"specular 0.5 roughness 0.15", &Finish::roughness, 0.15},
                      FinishCase{"specular 0.5", &Finish::roughness, 0.05},
                      FinishCase{"diffuse 0.7", &Finish::diffuse, 0.7},
                      FinishCase{"diffuse 0.7, 0.2", &Finish::diffuse_back, 0.2},
                      FinishCase{"diffuse 0.7 0.2", &Finish::diffuse_back, 0.2},   // the comma is optional
                      FinishCase{"diffuse 0.7, 0.2 diffuse 0.5", &Finish::diffuse_back, 0},
                      FinishCase{"brilliance 2", &Finish::brilliance, 2},
                      FinishCase{"ambient 0", &Finish::diffuse, 0.6}));

// Measured with POV-Ray 3.7.0.10: a finish { F diffuse 0 } whose F has `diffuse 0, 1` is black lit from behind —
// writing `diffuse` again without a back value sets the back value to 0.
TEST(Textures, DiffuseWithoutBackValueClearsTheCopiedOne) {
  const SceneDescription s = scene(
      "#declare F = finish { diffuse 0, 1 }\nsphere { 0, 1 finish { F } }\nsphere { 0, 1 finish { F diffuse 0 } }\n");
  ASSERT_EQ(s.objects.size(), 2u);
  EXPECT_EQ(top_layer(s.objects[0]).finish.diffuse_back, 1);
  EXPECT_EQ(top_layer(s.objects[1]).finish.diffuse_back, 0);
}

TEST(Textures, FinishColourParameters) {
  const SceneDescription s = scene(
      "sphere { 0, 1 finish { ambient 0.3 emission rgb <0.1,0.2,0.3> } }\n"
      "sphere { 0, 1 finish { ambient <0.1,0.2,0.3> } }\n");
  ASSERT_EQ(s.objects.size(), 2u);
  expect_colour(top_layer(s.objects[0]).finish.ambient, {0.3, 0.3, 0.3, 0, 0});
  expect_colour(top_layer(s.objects[0]).finish.emission, {0.1, 0.2, 0.3, 0, 0});
  expect_colour(top_layer(s.objects[1]).finish.ambient, {0.1, 0.2, 0.3, 0, 0});
}

TEST(Textures, PigmentForms) {
  const SceneDescription s = scene(
      "#declare Red = rgb <1,0,0>;\n"
      "sphere { 0, 1 pigment { checker } }\n"
      "sphere { 0, 1 pigment { checker rgb 1, rgb <1,0,0> } }\n"
      "sphere { 0, 1 pigment { checker Red } }\n"
      "sphere { 0, 1 pigment { Red } }\n"
      "sphere { 0, 1 pigment { color rgbt <0,1,0,0.5> } }\n");
  ASSERT_EQ(s.objects.size(), 5u);
  const Pigment& p0 = top_layer(s.objects[0]).pigment;
  EXPECT_EQ(p0.pattern, PatternKind::checker);
  ASSERT_EQ(p0.entries.size(), 2u);
  expect_colour(p0.entries[0].colour, {0, 0, 1, 0, 0});   // blue
  expect_colour(p0.entries[1].colour, {0, 1, 0, 0, 0});   // green
  const Pigment& p1 = top_layer(s.objects[1]).pigment;
  ASSERT_EQ(p1.entries.size(), 2u);
  expect_colour(p1.entries[0].colour, {1, 1, 1, 0, 0});
  expect_colour(p1.entries[1].colour, {1, 0, 0, 0, 0});
  const Pigment& p2 = top_layer(s.objects[2]).pigment;
  ASSERT_EQ(p2.entries.size(), 2u);
  expect_colour(p2.entries[0].colour, {1, 0, 0, 0, 0});
  expect_colour(p2.entries[1].colour, {0, 1, 0, 0, 0});   // the second stays at its default
  EXPECT_EQ(top_layer(s.objects[3]).pigment.pattern, PatternKind::solid);
  expect_colour(top_layer(s.objects[3]).pigment.colour, {1, 0, 0, 0, 0});
  expect_colour(top_layer(s.objects[4]).pigment.colour, {0, 1, 0, 0, 0.5});
}

TEST(Textures, ATextureAfterATransformIsNotMovedByIt) {
  const SceneDescription s = scene(
      "sphere { 0, 1 translate x pigment { checker } }\n"
      "sphere { 0, 1 pigment { checker } translate x }\n"
      "sphere { 0, 1 pigment { checker scale 2 } translate x }\n"
      "sphere { 0, 1 texture { pigment { checker } translate y } rotate z*90 }\n");
  ASSERT_EQ(s.objects.size(), 4u);
  expect_matrix_near(top_layer(s.objects[0]).pigment.world_from_pattern, Matrix::identity());
  expect_matrix_near(s.objects[0].world_from_object, Matrix::translation({1, 0, 0}));
  expect_matrix_near(top_layer(s.objects[1]).pigment.world_from_pattern, Matrix::translation({1, 0, 0}));
  expect_matrix_near(top_layer(s.objects[2]).pigment.world_from_pattern,
                     Matrix::scaling({2, 2, 2}) * Matrix::translation({1, 0, 0}));
  expect_matrix_near(top_layer(s.objects[3]).pigment.world_from_pattern,
                     Matrix::translation({0, 1, 0}) * Matrix::rotation({0, 0, 90}));
}

TEST(Textures, TwoTextureBlocksMakeTwoLayersTheLastOnTop) {
  const SceneDescription s = scene(
      "sphere { 0, 1 texture { pigment { rgb 1 } } texture { pigment { rgbt <1,0,0,0.5> } finish { phong 1 } } }\n"
      "#declare T = texture { pigment { rgb 1 } } texture { pigment { rgbf <0,0,1,1> } }\n"
      "sphere { 0, 1 texture { T } }\n"
      "sphere { 0, 1 texture { T finish { phong 1 } } }\n");
  ASSERT_EQ(s.objects.size(), 3u);
  const Texture& t0 = *s.objects[0].texture;
  ASSERT_EQ(t0.layers.size(), 2u);
  expect_colour(t0.layers[0].pigment.colour, {1, 1, 1, 0, 0});
  expect_colour(t0.layers[1].pigment.colour, {1, 0, 0, 0, 0.5});
  EXPECT_EQ(t0.layers[0].finish.phong, 0);
  EXPECT_EQ(t0.layers[1].finish.phong, 1);
  const Texture& t1 = *s.objects[1].texture;
  ASSERT_EQ(t1.layers.size(), 2u);
  expect_colour(t1.layers[1].pigment.colour, {0, 0, 1, 1, 0});
  // Editing a declared texture changes its top layer only (and not T itself).
  const Texture& t2 = *s.objects[2].texture;
  ASSERT_EQ(t2.layers.size(), 2u);
  EXPECT_EQ(t2.layers[0].finish.phong, 0);
  EXPECT_EQ(t2.layers[1].finish.phong, 1);
  EXPECT_EQ(t1.layers[1].finish.phong, 0);
}

TEST(Textures, TextureEditsKeepTheOtherValues) {
  const SceneDescription s = scene(
      "#declare T = texture { pigment { rgb <1,0,0> } finish { specular 0.5 roughness 0.1 } }\n"
      "sphere { 0, 1 texture { T finish { phong 1 } } }\n"
      "sphere { 0, 1 texture { T pigment { rgb <0,1,0> } } }\n"
      "sphere { 0, 1 texture { T } finish { ambient 0.2 } }\n");
  ASSERT_EQ(s.objects.size(), 3u);
  const Finish& f0 = top_layer(s.objects[0]).finish;
  EXPECT_EQ(f0.phong, 1);
  EXPECT_EQ(f0.specular, 0.5);
  EXPECT_EQ(f0.roughness, 0.1);
  expect_colour(top_layer(s.objects[0]).pigment.colour, {1, 0, 0, 0, 0});
  expect_colour(top_layer(s.objects[1]).pigment.colour, {0, 1, 0, 0, 0});
  EXPECT_EQ(top_layer(s.objects[1]).finish.specular, 0.5);
  // An object-level finish on a textured object edits its top layer in place.
  ASSERT_EQ(s.objects[2].texture->layers.size(), 1u);
  expect_colour(top_layer(s.objects[2]).finish.ambient, {0.2, 0.2, 0.2, 0, 0});
  EXPECT_EQ(top_layer(s.objects[2]).finish.specular, 0.5);
}

TEST(Textures, DefaultFinishAffectsOnlyLaterObjects) {
  const SceneDescription s = scene(
      "sphere { 0, 1 }\n"
      "#declare Early = sphere { 0, 2 }\n"
      "#declare EarlyFinish = finish { phong 1 }\n"
      "#default { finish { ambient 0.5 } }\n"
      "sphere { 0, 1 }\n"
      "object { Early }\n"
      "sphere { 0, 1 finish { EarlyFinish } }\n"
      "sphere { 0, 1 pigment { rgb 1 } }\n");
  ASSERT_EQ(s.objects.size(), 5u);
  EXPECT_EQ(top_layer(s.objects[0]).finish.ambient.r, static_cast<float>(0.1));   // colours are single precision
  EXPECT_EQ(top_layer(s.objects[1]).finish.ambient.r, 0.5);
  // An untextured declared object gets the default in force where it is placed ([V sdl_tex_order]).
  EXPECT_EQ(top_layer(s.objects[2]).finish.ambient.r, 0.5);
  // A finish declared before the #default keeps the old default values.
  EXPECT_EQ(top_layer(s.objects[3]).finish.ambient.r, static_cast<float>(0.1));
  EXPECT_EQ(top_layer(s.objects[3]).finish.phong, 1);
  EXPECT_EQ(top_layer(s.objects[4]).finish.ambient.r, 0.5);
}

TEST(Textures, DefaultPigment) {
  const SceneDescription s = scene("#default { pigment { rgb <1,0,0> } }\nsphere { 0, 1 }\n");
  ASSERT_EQ(s.objects.size(), 1u);
  expect_colour(top_layer(s.objects[0]).pigment.colour, {1, 0, 0, 0, 0});
}

// ---- Object copies -----------------------------------------------------------------------------------------
TEST(Objects, PolyAboveOrderFourIsRenderedAndKeepsPovRaysComposedInverse) {
  // Orders 5 … 35 are rendered (no longer refused). The inverse is composed from each transform's own inverse in
  // reverse order, as POV-Ray's Compose_Transforms does: scale 1/4 exactly, then the translation negated.
  std::string terms = "1";
  for (int i = 1; i < 56; ++i) terms += i == 55 ? ", -1" : ", 0";
  const SceneDescription s = scene("poly { 5, <" + terms + "> sturm scale 4 translate <1, 2, 3> }\n");
  ASSERT_EQ(s.objects.size(), 1u);
  const Object& o = s.objects[0];
  EXPECT_FALSE(o.unsupported);
  const auto& poly = std::get<Poly>(o.shape);
  EXPECT_EQ(poly.order, 5);
  EXPECT_TRUE(poly.sturm);
  // Row vectors (p · M): the later transform's inverse applies first.
  const Matrix expected = Matrix::translation({-1, -2, -3}) * Matrix::scaling({0.25, 0.25, 0.25});
  const Vec3 back = poly.object_from_world.point(o.world_from_object.point({0.5, -0.75, 2}));
  EXPECT_EQ(back.x, 0.5);
  EXPECT_EQ(back.y, -0.75);
  EXPECT_EQ(back.z, 2.0);
  EXPECT_TRUE(poly.object_from_world == expected);
}

TEST(Objects, ObjectIdentifierIsADeepCopy) {
  const SceneDescription s = scene(
      "#declare S = sphere { <1,0,0>, 1 pigment { checker } }\n"
      "object { S translate y }\n"
      "object { S }\n"
      "object { S pigment { rgb 1 } }\n"
      "object { S texture { pigment { rgbt <1,0,0,0.5> } } }\n"
      "S\n");
  ASSERT_EQ(s.objects.size(), 5u);
  expect_matrix_near(s.objects[0].world_from_object, Matrix::translation({0, 1, 0}));
  expect_matrix_near(top_layer(s.objects[0]).pigment.world_from_pattern, Matrix::translation({0, 1, 0}));
  // The declared object itself was not moved by the first copy.
  expect_matrix_near(s.objects[1].world_from_object, Matrix::identity());
  expect_matrix_near(top_layer(s.objects[1]).pigment.world_from_pattern, Matrix::identity());
  EXPECT_EQ(top_layer(s.objects[1]).pigment.pattern, PatternKind::checker);
  // A pigment edits the copy's top layer; a texture is layered on top of the one it has.
  EXPECT_EQ(top_layer(s.objects[2]).pigment.pattern, PatternKind::solid);
  EXPECT_EQ(top_layer(s.objects[4]).pigment.pattern, PatternKind::checker);
  ASSERT_EQ(s.objects[3].texture->layers.size(), 2u);
  EXPECT_EQ(s.objects[3].texture->layers[0].pigment.pattern, PatternKind::checker);
  expect_colour(s.objects[3].texture->layers[1].pigment.colour, {1, 0, 0, 0, 0.5});
  EXPECT_EQ(std::get<Sphere>(s.objects[4].shape).centre, (Vec3{1, 0, 0}));
}

// A solid-coloured texture renders the same however it is moved: copies moved by transforms share the declared
// object's texture, yet a pigment edited after the transforms starts from the moved one, as when it is copied. When
// an object is placed, the transforms the parser still keeps for its texture are ones the texture ignores (those for
// a texture edited since were applied); they go with the notes.
TEST(Objects, MovedCopiesOfASolidTexturedObjectShareItsTexture) {
  ParseOptions options;
  options.message_sink = [](const std::string&) {};
  int placed = 0;
  options.placing = [&placed](const Object& o) {
    ++placed;
    const bool kept = sdl::notes_of(o).deferred_texture_transform.has_value();
    EXPECT_TRUE(!kept || texture_ignores_transforms(*o.texture)) << "object " << placed;
  };
  const SceneDescription s = parse_scene_text(
      "#version 3.7;\n"
      "#declare S = sphere { 0, 1 texture { pigment { rgb 1 } finish { phong 0.5 } } }\n"
      "object { S translate x }\n"
      "object { S translate y rotate z*30 }\n"
      "object { S translate x scale 2 pigment { checker } }\n"
      "object { S translate x normal { bumps } pigment { checker } }\n"
      "object { S translate x texture { pigment { checker } } }\n"
      "object { S translate x material { texture { pigment { checker } } } }\n",
      "test.pov", options);
  ASSERT_EQ(s.objects.size(), 6u);
  EXPECT_EQ(placed, 6);
  EXPECT_EQ(s.objects[0].texture, s.objects[1].texture);
  expect_matrix_near(top_layer(s.objects[2]).pigment.world_from_pattern,
                     Matrix::translation({1, 0, 0}) * Matrix::scaling({2, 2, 2}));
  expect_matrix_near(top_layer(s.objects[3]).pigment.world_from_pattern, Matrix::translation({1, 0, 0}));
  ASSERT_EQ(s.objects[4].texture->layers.size(), 2u);
  expect_matrix_near(s.objects[4].texture->layers[0].pigment.world_from_pattern, Matrix::translation({1, 0, 0}));
  expect_matrix_near(top_layer(s.objects[4]).pigment.world_from_pattern, Matrix::identity());
  expect_matrix_near(top_layer(s.objects[5]).pigment.world_from_pattern, Matrix::identity());
}

TEST(Objects, NestedObjectCopiesCompose) {
  const SceneDescription s = scene(
      "#declare A = sphere { 0, 1 translate x }\n"
      "#declare B = object { A rotate y*90 }\n"
      "object { B scale 2 }\n");
  ASSERT_EQ(s.objects.size(), 1u);
  expect_vec_near(s.objects[0].world_from_object.point({0, 0, 0}), {0, 0, -2}, 1e-12);
}

// The parser's notes on an object (its box state, transforms kept for a texture) are parser business: every object
// of a returned scene, down to CSG children, clip and bounding objects and lights' looks_like objects, holds none,
// though objects had them when they were placed.
void expect_no_parser_notes(const Object& o, const std::string& what) {
  EXPECT_EQ(o.parser_notes, nullptr) << what;
  const std::pair<const std::vector<Object>*, const char*> lists[] = {
      {&o.clipped_by, " clip "}, {&o.bounded_by, " bound "}, {&o.removed_bounds, " removed bound "}};
  for (const auto& [list, name] : lists)
    for (std::size_t i = 0; i < list->size(); ++i) expect_no_parser_notes((*list)[i], what + name + std::to_string(i));
  if (const auto* csg = std::get_if<Csg>(&o.shape)) {
    for (std::size_t i = 0; i < csg->children.size(); ++i)
      expect_no_parser_notes(csg->children[i], what + " child " + std::to_string(i));
    for (const Light& light : csg->lights)
      for (const Object& shown : light.looks_like) expect_no_parser_notes(shown, what + " looks_like");
  }
}

TEST(Objects, ReturnedSceneHoldsNoParserNotes) {
  ParseOptions options;
  options.message_sink = [](const std::string&) {};
  int placed_with_notes = 0;
  options.placing = [&placed_with_notes](const Object& o) { placed_with_notes += o.parser_notes != nullptr; };
  const SceneDescription s = parse_scene_text(
      "#version 3.7;\n"
      "#declare S = sphere { 0, 1 pigment { rgb 1 } translate x }\n"
      "object { S }\n"
      "object { S scale <1,2,3> rotate 10*y }\n"
      "plane { y, 1 matrix <1,0,0, 0,1,0, 0,0,1, 1,2,3> clipped_by { box { -1, 1 translate y } } }\n"
      "quartic { <1,0,0,0,0,0,0,0,0,0, 0,0,0,0,0,0,0,0,0,0, 0,0,0,0,0,0,0,0,0,0, 0,0,0,0,-1>\n"
      "  clipped_by { sphere { 0, 2 } } scale 2 }\n"
      "quadric { <1,1,1>, <0,0,0>, <0,0,0>, -1 bounded_by { box { -2, 2 } } rotate 10*x }\n"
      "union {\n"
      "  sphere { 0, 1 clipped_by { box { 0, 2 rotate 5*z } } }\n"
      "  intersection { sphere { 0, 2 scale <1,2,1> } plane { y, 0.5 } quadric { <1,1,1>, <0,0,0>, <0,0,0>, -1 } }\n"
      "  difference { box { -1, 1 } object { S } }\n"
      "  light_source { <1,2,3> rgb 1 looks_like { sphere { 0, 0.1 translate y } } }\n"
      "  translate z }\n"
      "merge { sphere { 0, 1 } sphere { x, 1 } bounded_by { box { -1, <2,1,1> } } scale 3 }\n"
      "blob { threshold 0.5 sphere { 0, 1, 1 } cylinder { 0, x, 0.5, 1 } scale <1,2,1> }\n"
      "mesh { triangle { <0.5,0.25,1>, <1,1.5,0.75>, <2,0.5,1.25> } rotate 20*z }\n"
      "sphere { 0, 1 bounded_by { box { -1, 1 } } translate x }\n"
      "light_source { <0,5,0> rgb 1 looks_like { box { -1, 1 pigment { rgb 1 } rotate 30*x } } translate x }\n",
      "test.pov", options);
  ASSERT_EQ(s.objects.size(), 12u);
  EXPECT_EQ(placed_with_notes, 12);   // every object had notes to drop
  for (std::size_t i = 0; i < s.objects.size(); ++i) expect_no_parser_notes(s.objects[i], "object " + std::to_string(i));
  ASSERT_FALSE(s.objects[10].removed_bounds.empty());   // the bounds POV-Ray removed were checked too
  for (const Light& light : s.lights) EXPECT_TRUE(light.looks_like.empty());
}

// ---- Global settings and background -------------------------------------------------------------------------
TEST(GlobalSettings, DefaultsAndValues) {
  const SceneDescription d = scene("");
  EXPECT_FALSE(d.settings.assumed_gamma.has_value());
  EXPECT_EQ(d.settings.max_trace_level, 5);
  EXPECT_NEAR(d.settings.adc_bailout, 1.0 / 255, 1e-15);
  expect_colour(d.settings.ambient_light, {1, 1, 1, 0, 0});

  const SceneDescription s =
      scene("global_settings { assumed_gamma 2.2 max_trace_level 12 adc_bailout 0.01 ambient_light rgb 0.5 }\n");
  ASSERT_TRUE(s.settings.assumed_gamma.has_value());
  EXPECT_EQ(*s.settings.assumed_gamma, 2.2);
  EXPECT_EQ(s.settings.max_trace_level, 12);
  EXPECT_EQ(s.settings.adc_bailout, 0.01);
  expect_colour(s.settings.ambient_light, {0.5, 0.5, 0.5, 0, 0});
}

TEST(GlobalSettings, MaxTraceLevelIsClamped) {
  EXPECT_EQ(scene("global_settings { max_trace_level 1000 }").settings.max_trace_level, 256);
  EXPECT_EQ(scene("global_settings { max_trace_level 0 }").settings.max_trace_level, 1);
  EXPECT_EQ(scene("global_settings { max_trace_level 1 }").settings.max_trace_level, 1);
}

// number_of_waves (truncated; below 1 becomes 1 with POV-Ray's warning) and hf_gray_16, which POV-Ray 3.7 ignores
// with a warning (an optional float may follow it).
TEST(GlobalSettings, NumberOfWavesAndTheIgnoredHfGray16) {
  EXPECT_EQ(scene("").settings.number_of_waves, 10);
  EXPECT_EQ(scene("global_settings { number_of_waves 3.9 }").settings.number_of_waves, 3);
  Messages m;
  EXPECT_EQ(parse("#version 3.7;\nglobal_settings { number_of_waves 0 hf_gray_16 on }\n", &m).settings.number_of_waves, 1);
  EXPECT_NE(m.joined().find("number_of_waves must be greater than 0"), std::string::npos) << m.joined();
  EXPECT_NE(m.joined().find("'hf_gray_16' setting here is ignored"), std::string::npos) << m.joined();
  EXPECT_NE(std::string(parse_error("#version 3.7;\nglobal_settings { number_of_waves 1e9 }\n").what())
                .find("number_of_waves above 65536"),
            std::string::npos);
}

TEST(GlobalSettings, SeveralBlocksAccumulate) {
  const SceneDescription s =
      scene("global_settings { assumed_gamma 1 }\nglobal_settings { max_trace_level 7 }\n");
  EXPECT_EQ(s.settings.assumed_gamma.value_or(0), 1);
  EXPECT_EQ(s.settings.max_trace_level, 7);
}

TEST(Background, DefaultIsTransparentBlack) {
  expect_colour(scene("").background, {0, 0, 0, 0, 1});
  expect_colour(scene("background { color rgb <1,0.5,0> }").background, {1, 0.5, 0, 0, 0});
  expect_colour(scene("background { rgbt <0,0,1,0.25> }").background, {0, 0, 1, 0, 0.25});
}

TEST(Camera, NonPlanarProjectionsKeepTheirAngles) {
  // POV-Ray's Parse_Camera: angle scales the direction only for perspective and orthographic cameras; the others
  // read it as written (default 90); spherical takes `angle H [, V]` with V = H/2 by default.
  const Camera f = camera_of("camera { fisheye angle 180 }");
  EXPECT_EQ(f.projection, Projection::fisheye);
  EXPECT_EQ(f.angle, 180);
  expect_vec_near(f.direction, {0, 0, 1});
  EXPECT_EQ(camera_of("camera { ultra_wide_angle }").angle, 90);
  const Camera s = camera_of("camera { spherical angle 300 }");
  EXPECT_EQ(s.h_angle, 300);
  EXPECT_EQ(s.v_angle, 150);
  EXPECT_EQ(camera_of("camera { spherical angle 300, 100 }").v_angle, 100);
  EXPECT_EQ(camera_of("camera { cylinder 3 }").projection, Projection::cylinder3);
  const ParseError e = parse_error("#version 3.7;\ncamera { cylinder 5 }\n");
  EXPECT_NE(std::string(e.what()).find("invalid cylinder camera type"), std::string::npos) << e.what();
}

TEST(Scene, VersionGiven) {
  EXPECT_TRUE(parse("#version 3.7;\nsphere{0,1}").version_given);
  EXPECT_FALSE(parse("sphere{0,1}").version_given);
  EXPECT_FALSE(parse("global_settings { assumed_gamma 1 }\n#version 3.7;\n").version_given);
  EXPECT_EQ(parse("#version 3.6;\n").language_version, 360);
}

}  // namespace
// POV-Ray's old syntax `texture { P N F … }`: bare pigment, normal and finish identifiers before anything else
// replace the layer's own; a pre-1.5 scene is warned, a 3.7 one is not.
TEST(Textures, BarePigmentNormalAndFinishIdentifiers) {
  const std::string declares =
      "#declare P = pigment { rgb <0, 1, 0> }\n#declare N = normal { bumps 0.5 }\n"
      "#declare F = finish { phong 0.7 }\n";
  Messages messages;
  const SceneDescription s =
      parse("#version 3.7;\n" + declares + "sphere { 0, 1 texture { F P N scale 2 finish { diffuse 0.3 } } }\n",
            &messages);
  const TextureLayer& l = top_layer(s.objects.at(0));
  expect_colour(l.pigment.colour, {0, 1, 0, 0, 0});
  ASSERT_TRUE(l.normal);
  EXPECT_EQ(l.normal->kind, NormalKind::bumps);
  EXPECT_EQ(l.finish.phong, 0.7);
  EXPECT_EQ(l.finish.diffuse, 0.3);   // the statements after the identifiers still edit the layer
  EXPECT_EQ(messages.joined().find("should be in"), std::string::npos);
  Messages old;
  parse("#version 1.0;\n" + declares + "sphere { 0, 1 texture { P } }\n", &old);
  EXPECT_NE(old.joined().find("Found 'pigment identifier' that should be in 'pigment' statement."), std::string::npos);
  // After a pigment statement a bare identifier is an error, as in POV-Ray.
  EXPECT_THROW(parse("#version 3.7;\n" + declares + "sphere { 0, 1 texture { pigment { P } F } }\n"), std::exception);
}

// quick_color is read and, at the full quality povtrace renders at, unused (POV-Ray uses it at +Q5 and below).
TEST(Textures, QuickColourIsReadAndDoesNotChangeThePigment) {
  const SceneDescription with = scene("sphere { 0, 1 pigment { rgb <0, 0, 1> quick_color rgb <1, 0, 0> } }\n");
  const SceneDescription without = scene("sphere { 0, 1 pigment { rgb <0, 0, 1> } }\n");
  expect_colour(top_layer(with.objects.at(0)).pigment.colour, {0, 0, 1, 0, 0});
  EXPECT_FALSE(with.objects.at(0).texture->unsupported);
  EXPECT_EQ(top_layer(with.objects.at(0)).pigment.pattern, top_layer(without.objects.at(0)).pigment.pattern);
  EXPECT_THROW(scene("sphere { 0, 1 pigment { rgb 1 quick_colour } }\n"), std::exception);   // a colour must follow
}

}  // namespace povtrace::test

