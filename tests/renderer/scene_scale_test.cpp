// Scale invariance (renderer/scene_scale.cpp): the rescaling factor and what a rescaled scene carries.
#include <gtest/gtest.h>

#include <cmath>

#include "renderer/scene_scale.hpp"
#include "scene_kit.hpp"

namespace {

using namespace povtrace;
using namespace povtrace::render;
using namespace povtrace::render::test;

TEST(SceneScale, OrdinarySizesAreLeftAlone) {
  for (double size : {0.05, 0.09, 1.0, 26.0, 1000.0, 1e4})
    EXPECT_EQ(normalizing_scale(ObjectSizes{size, size, size}), 1.0) << size;
  EXPECT_EQ(normalizing_scale(ObjectSizes{}), 1.0);   // only unbounded shapes: nothing to go by
  EXPECT_EQ(normalizing_scale(ObjectSizes{0.001, 1, 1e6}), 1.0);   // mixed scales: as written
}

TEST(SceneScale, TinyAndHugeObjectsGetAPowerOfTwoTowardsTwo) {
  for (double size : {1.5e-5, 0.02, 2e5, 1.5e7}) {
    const double k = normalizing_scale(ObjectSizes{size / 3, size, size * 2});
    EXPECT_EQ(std::exp2(std::round(std::log2(k))), k) << size;   // exact in floating point
    EXPECT_GE(size * k, 2.0 / std::sqrt(2.0)) << size;
    EXPECT_LE(size * k, 2.0 * std::sqrt(2.0)) << size;
  }
}

// Huge objects alone are no reason to shrink a scene: POV-Ray's absolute tolerances are small against them, and
// shrinking would bring small gaps between them down to those tolerances (advanced/mediasky.pov: sky shells 1 unit
// apart around a planet of radius 5e4 lost their media). Only when some ray may reach MAX_DISTANCE (an unbounded
// object, or objects half of it away from the camera) is the scene rescaled.
TEST(SceneScale, HugeObjectsNearTheCameraAreLeftAsWritten) {
  SceneDescription s = base_scene();
  s.objects.push_back(sphere_object({0, -5e4, 0}, 5e4, texture(rgb(1, 1, 1))));
  s.objects.push_back(sphere_object({0, -5e4, 0}, 5.1e4, texture(rgb(1, 0, 0))));
  EXPECT_EQ(build_render_scene(s, BuildOptions{}).scale, 1.0);
  SceneDescription with_plane = s;
  with_plane.objects.push_back(plane_object({0, 1, 0}, -2e5, texture(rgb(0, 1, 0))));
  EXPECT_LT(build_render_scene(with_plane, BuildOptions{}).scale, 1.0);
  SceneDescription far = s;
  far.objects.push_back(sphere_object({0, 0, 6e6}, 4e4, texture(rgb(0, 1, 0))));
  EXPECT_LT(build_render_scene(far, BuildOptions{}).scale, 1.0);
}

// A rescaled scene moves and rescales each object's media on its own copy, but CSG children that inherited one
// interior must stay one interior (same_interior compares media_id), or rays entering one child and leaving by
// another lose track of the media they are in.
TEST(SceneScale, RescalingKeepsInheritedMediaOneInterior) {
  Interior in;
  in.hollow = true;
  Media m;
  m.absorption = Colour{0.5, 0.5, 0.5, 0, 0};
  m.densities.push_back(Pigment{});
  in.media = std::make_shared<const std::vector<Media>>(std::vector<Media>{m});
  in.media_id = 7;
  Object shell;
  Csg csg;
  csg.kind = CsgKind::difference;
  csg.children.push_back(sphere_object({0, 0, 0}, 2e5, texture(rgb(1, 1, 1))));
  csg.children.push_back(sphere_object({0, 0, 0}, 1.9e5, texture(rgb(1, 1, 1))));
  for (Object& child : csg.children) child.interior = in;
  shell.shape = csg;
  shell.interior = in;
  SceneDescription s = base_scene();
  s.objects.push_back(shell);
  const SceneDescription scaled = scaled_scene(s, 0.25);
  const auto& children = std::get<Csg>(scaled.objects[0].shape).children;
  EXPECT_EQ(children[0].interior->media_id, children[1].interior->media_id);
  EXPECT_EQ(children[0].interior->media->front().absorption.r, 2.0);   // per unit length: 4 times as much
  EXPECT_NE(children[0].interior->media.get(), in.media.get());         // the original is left as it was
}

// The objects decide, not the scene's extent: a sky sphere of radius 1e5 (textures/finishes/cluster.pov,
// advanced/quilt1.pov) around ordinary objects leaves the scene as written, as POV-Ray renders it; shrinking it to
// an ordinary extent would have shrunk the objects to POV-Ray's tolerances and lost their shadows. Tiny objects
// alone are rescaled; around a sky sphere they are left as written too (as POV-Ray renders them).
TEST(SceneScale, ASkySphereAroundOrdinaryObjectsIsNoReasonToRescale) {
  SceneDescription s = base_scene();
  s.objects.push_back(sphere_object({0, 0, 0}, 1e5, texture(rgb(1, 1, 1))));
  s.objects.push_back(sphere_object({0, 1, 0}, 1, texture(rgb(1, 0, 0))));
  s.objects.push_back(sphere_object({2, 1, 0}, 0.5, texture(rgb(0, 1, 0))));
  EXPECT_EQ(build_render_scene(s, BuildOptions{}).scale, 1.0);
  SceneDescription tiny = base_scene();
  tiny.objects.push_back(sphere_object({0, 0, 0}, 1e5, texture(rgb(1, 1, 1))));
  tiny.objects.push_back(sphere_object({0, 1e-4, 0}, 1e-4, texture(rgb(1, 0, 0))));
  tiny.objects.push_back(sphere_object({2e-4, 1e-4, 0}, 5e-5, texture(rgb(0, 1, 0))));
  EXPECT_EQ(build_render_scene(tiny, BuildOptions{}).scale, 1.0);
  SceneDescription alone = base_scene();
  alone.objects.push_back(sphere_object({0, 1e-4, 0}, 1e-4, texture(rgb(1, 0, 0))));
  alone.objects.push_back(sphere_object({2e-4, 1e-4, 0}, 5e-5, texture(rgb(0, 1, 0))));
  EXPECT_NE(build_render_scene(alone, BuildOptions{}).scale, 1.0);
}

TEST(SceneScale, EveryLengthIsScaled) {
  SceneDescription s = base_scene();
  Object glass = sphere_object({1, 2, 3}, 0.5, texture(rgb(1, 1, 1)));
  glass.interior = Interior{};
  glass.interior->fade_distance = 2;
  s.objects.push_back(glass);
  Light l = point_light({4, 5, 6});
  l.fade_distance = 3;
  l.cylinder = true;
  l.radius = 0.75;
  l.falloff = 1;
  l.area = true;
  l.axis1 = {1, 0, 0};
  s.lights.push_back(l);
  Fog f;
  f.distance = 10;
  f.alt = 1;
  f.offset = 0.5;
  s.fogs.push_back(f);
  const SceneDescription t = scaled_scene(s, 4);
  EXPECT_EQ(t.objects[0].world_from_object.point({1, 2, 3}), (Vec3{4, 8, 12}));
  EXPECT_EQ(t.objects[0].interior->fade_distance, 8);
  EXPECT_EQ(t.lights[0].location, (Vec3{16, 20, 24}));
  EXPECT_EQ(t.lights[0].fade_distance, 12);
  EXPECT_EQ(t.lights[0].radius, 3);
  EXPECT_EQ(t.lights[0].falloff, 4);
  EXPECT_EQ(t.lights[0].axis1, (Vec3{4, 0, 0}));
  EXPECT_EQ(t.fogs[0].distance, 40);
  EXPECT_EQ(t.fogs[0].alt, 4);
  EXPECT_EQ(t.fogs[0].offset, 2);
  EXPECT_EQ(t.camera.location, s.camera.location * 4.0);
  EXPECT_EQ(t.camera.right, s.camera.right * 4.0);
}

TEST(SceneScale, ATinySceneIsBuiltRescaledUnlessPovrayTolerancesAreAsked) {
  SceneDescription s = base_scene();
  s.camera.location = {0, 0, -1e-5};
  s.objects.push_back(sphere_object({0, 0, 0}, 1e-6, texture(rgb(1, 1, 1))));
  EXPECT_NE(build_render_scene(s, BuildOptions{}).scale, 1.0);
  BuildOptions povray;
  povray.povray_tolerances = true;
  EXPECT_EQ(build_render_scene(s, povray).scale, 1.0);
}

}  // namespace
