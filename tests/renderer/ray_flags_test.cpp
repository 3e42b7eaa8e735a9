// The object modifiers no_image and no_reflection (POV-Ray 3.7: NoSomethingFlagRayObjectCondition for top-level
// objects, csg.cpp Test_Ray_Flags for union children and Test_Ray_Flags_Shadow for merge children, Ray::SetFlags
// for the kinds of secondary rays): which ray kinds see which objects, through the accelerator and through the
// tracer's camera, reflected, refracted and shadow rays.
#include <gtest/gtest.h>

#include <cstdint>

#include "scene_kit.hpp"

namespace {

using namespace povtrace;
using namespace povtrace::render;
using namespace povtrace::render::test;

constexpr std::uint8_t kKinds[] = {ray_kind::other, ray_kind::primary, ray_kind::reflected, ray_kind::refracted,
                                   ray_kind::reflected_refracted};

TEST(RayKinds, FlagsAccumulateAsInPovRay) {
  using namespace ray_kind;
  EXPECT_EQ(after_reflection(primary), reflected);
  EXPECT_EQ(after_refraction(primary), refracted);
  EXPECT_EQ(after_reflection(reflected), reflected);
  EXPECT_EQ(after_refraction(refracted), refracted);
  EXPECT_EQ(after_reflection(refracted), reflected_refracted);
  EXPECT_EQ(after_refraction(reflected), reflected_refracted);
  EXPECT_EQ(after_reflection(reflected_refracted), reflected_refracted);
  EXPECT_EQ(after_refraction(reflected_refracted), reflected_refracted);
  EXPECT_EQ(after_reflection(other), other);   // scenes without flags keep every ray `other`
  EXPECT_EQ(after_refraction(other), other);
}

Object flagged(Object o, bool no_image, bool no_reflection) {
  o.no_image = no_image;
  o.no_reflection = no_reflection;
  return o;
}

Object csg(CsgKind kind, std::vector<Object> children) {
  Object o;
  o.shape = Csg{kind, std::move(children), {}};
  o.texture = texture(rgb(1, 1, 1));
  return o;
}

// The depth of the nearest hit of a ray of `kind` straight along +z from (x, 0, −10), or −1 for none.
double depth_seen(const RenderScene& rs, double x, std::uint8_t kind) {
  const Hit h = rs.accelerator.closest_hit(Ray{{x, 0, -10}, {0, 0, 1}, kind}, tolerance::min_isect_depth,
                                           tolerance::bound_huge);
  return h.found() ? h.t : -1;
}

// Whether the kind sees the object at x, as POV-Ray's top-level test says.
void expect_seen_by(const RenderScene& rs, double x, bool image, bool reflection, bool refracted_reflected) {
  EXPECT_GT(depth_seen(rs, x, ray_kind::other), 0) << x;
  EXPECT_EQ(depth_seen(rs, x, ray_kind::primary) > 0, image) << x;
  EXPECT_EQ(depth_seen(rs, x, ray_kind::refracted) > 0, image) << x;
  EXPECT_EQ(depth_seen(rs, x, ray_kind::reflected) > 0, reflection) << x;
  EXPECT_EQ(depth_seen(rs, x, ray_kind::reflected_refracted) > 0, refracted_reflected) << x;
}

TEST(RayFlags, TopLevelObjectsAreSkippedByTheirKinds) {
  SceneDescription s = base_scene();
  const auto white = texture(rgb(1, 1, 1));
  s.objects.push_back(flagged(sphere_object({0, 0, 0}, 1, white), true, false));
  s.objects.push_back(flagged(sphere_object({3, 0, 0}, 1, white), false, true));
  s.objects.push_back(flagged(sphere_object({6, 0, 0}, 1, white), true, true));
  s.objects.push_back(sphere_object({9, 0, 0}, 1, white));
  const RenderScene rs = build_render_scene(s, BuildOptions{});
  EXPECT_TRUE(rs.any_ray_flags);
  // no_image: image rays (primary, refracted only) skip it; with a reflection in the history it is seen.
  expect_seen_by(rs, 0, false, true, true);
  // no_reflection: every ray with a reflection in its history skips it.
  expect_seen_by(rs, 3, true, false, false);
  expect_seen_by(rs, 6, false, false, false);
  expect_seen_by(rs, 9, true, true, true);
  // Shadow rays see all of them.
  for (const double x : {0.0, 3.0, 6.0, 9.0}) {
    int crossings = 0;
    rs.accelerator.for_each_shadow_hit(Ray{{x, 0, -10}, {0, 0, 1}}, tolerance::shadow, 100,
                                       [&](std::uint32_t, const SurfaceHit&) { ++crossings; });
    EXPECT_EQ(crossings, 2) << x;
  }
}

TEST(RayFlags, ScenesWithoutFlagsTraceEveryRayAsOther) {
  SceneDescription s = base_scene();
  s.objects.push_back(sphere_object({0, 0, 0}, 1, texture(rgb(1, 1, 1))));
  EXPECT_FALSE(build_render_scene(s, BuildOptions{}).any_ray_flags);
  SceneDescription nested = base_scene();
  nested.objects.push_back(csg(CsgKind::merge, {sphere_object({0, 0, 0}, 1, texture(rgb(1, 1, 1))),
                                                flagged(sphere_object({1, 0, 0}, 1, texture(rgb(1, 1, 1))), false,
                                                        true)}));
  EXPECT_TRUE(build_render_scene(nested, BuildOptions{}).any_ray_flags);
}

// A union split into its children (no clip, no bound) leaves top-level objects: a no_image child is hidden from
// camera rays. A union kept whole (here clipped) tests its children with Test_Ray_Flags: camera rays still see a
// no_image child, refracted image rays do not; no_reflection children are skipped by reflection-flagged rays.
TEST(RayFlags, UnionChildrenSplitOrKeptWhole) {
  const auto white = texture(rgb(1, 1, 1));
  for (const bool clipped : {false, true}) {
    SceneDescription s = base_scene();
    Object u = csg(CsgKind::union_, {sphere_object({0, 0, 0}, 1, white),
                                     flagged(sphere_object({3, 0, 0}, 1, white), true, false),
                                     flagged(sphere_object({6, 0, 0}, 1, white), false, true)});
    if (clipped) u.clipped_by.push_back(box_object({-20, -20, -20}, {20, 20, 20}, nullptr));
    s.objects.push_back(u);
    const RenderScene rs = build_render_scene(s, BuildOptions{});
    SCOPED_TRACE(clipped ? "clipped" : "split");
    EXPECT_EQ(rs.accelerator.primitives().size(), clipped ? 1u : 3u);
    for (const std::uint8_t k : kKinds) EXPECT_REL(depth_seen(rs, 0, k), 9.0);
    EXPECT_EQ(depth_seen(rs, 3, ray_kind::primary) > 0, clipped);   // the union-children quirk
    EXPECT_LT(depth_seen(rs, 3, ray_kind::refracted), 0);
    EXPECT_GT(depth_seen(rs, 3, ray_kind::reflected), 0);
    EXPECT_GT(depth_seen(rs, 3, ray_kind::reflected_refracted), 0);
    EXPECT_GT(depth_seen(rs, 6, ray_kind::primary), 0);
    EXPECT_GT(depth_seen(rs, 6, ray_kind::refracted), 0);
    EXPECT_LT(depth_seen(rs, 6, ray_kind::reflected), 0);
    EXPECT_LT(depth_seen(rs, 6, ray_kind::reflected_refracted), 0);
  }
}

// Sphere A (centre 0, front at z = −1) and a no_image sphere B (centre z = −0.5, front at z = −1.5). A merge skips
// B for image rays, for its hits and for the inside test that would remove A's front inside B; a kept-whole union
// lets camera rays see B; an intersection does not test its children.
TEST(RayFlags, MergeAndIntersectionChildren) {
  const auto white = texture(rgb(1, 1, 1));
  auto with = [&](CsgKind kind) {
    SceneDescription s = base_scene();
    Object a = sphere_object({0, 0, 0}, 1, white);
    Object b = flagged(sphere_object({0, 0, -0.5}, 1, white), true, false);
    if (kind == CsgKind::intersection) std::swap(a.no_image, b.no_image);   // the flag on A, whose front counts
    Object o = csg(kind, {a, b});
    o.clipped_by.push_back(box_object({-20, -20, -20}, {20, 20, 20}, nullptr));   // keeps a union whole
    s.objects.push_back(o);
    return build_render_scene(s, BuildOptions{});
  };
  const RenderScene merge = with(CsgKind::merge);
  EXPECT_REL(depth_seen(merge, 0, ray_kind::primary), 9.0);
  EXPECT_REL(depth_seen(merge, 0, ray_kind::refracted), 9.0);
  EXPECT_REL(depth_seen(merge, 0, ray_kind::reflected), 8.5);
  EXPECT_REL(depth_seen(merge, 0, ray_kind::other), 8.5);
  const RenderScene u = with(CsgKind::union_);
  EXPECT_REL(depth_seen(u, 0, ray_kind::primary), 8.5);
  EXPECT_REL(depth_seen(u, 0, ray_kind::refracted), 9.0);
  const RenderScene i = with(CsgKind::intersection);
  for (const std::uint8_t k : kKinds) EXPECT_REL(depth_seen(i, 0, k), 9.0);
}

// Through the tracer: a black mirror floor y = 0 under a blue sky, a red ambient sphere above it at z = 0. The
// camera ray at height 1 meets the sphere directly; the one aimed down at the floor at z = −5 meets it reflected.
// A fully transmitting window (ior 1) in front continues camera rays as refracted image rays.
struct MirrorScene {
  bool no_image = false, no_reflection = false, window = false, clipped_union = false;
  Rgb direct() const { return seen({0, 0, 1}); }
  Rgb reflected() const { return seen({0, -1, 5}); }
  Rgb seen(Vec3 direction) const {
    SceneDescription s = base_scene();
    s.background = rgb(0, 0, 1);
    Finish mirror = finish_ambient_diffuse(0, 0);
    mirror.reflection_min = mirror.reflection_max = rgb(1, 1, 1);
    s.objects.push_back(plane_object({0, 1, 0}, 0, texture(rgb(0, 0, 0), mirror)));
    Object ball = flagged(sphere_object({0, 1, 0}, 0.5, texture(rgb(1, 0, 0), finish_ambient_diffuse(1, 0))),
                          no_image, no_reflection);
    if (clipped_union) {
      Object u = csg(CsgKind::union_, {ball});
      u.clipped_by.push_back(box_object({-20, -20, -20}, {20, 20, 20}, nullptr));
      ball = u;
    }
    s.objects.push_back(ball);
    if (window) s.objects.push_back(box_object({-5, -1, -8}, {5, 5, -7.9}, texture(rgbft(1, 1, 1, 0, 1))));
    const RenderScene rs = build_render_scene(s, BuildOptions{});
    return trace_at(rs, {0, 1, -10}, direction).colour;
  }
};

TEST(RayFlags, TracerGivesCameraReflectedAndRefractedRaysTheirKinds) {
  const MirrorScene plain;
  EXPECT_RGB_REL(plain.direct(), 1, 0, 0);
  EXPECT_RGB_REL(plain.reflected(), 1, 0, 0);
  const MirrorScene hidden_image{true, false};
  EXPECT_RGB_REL(hidden_image.direct(), 0, 0, 1);
  EXPECT_RGB_REL(hidden_image.reflected(), 1, 0, 0);
  const MirrorScene hidden_reflection{false, true};
  EXPECT_RGB_REL(hidden_reflection.direct(), 1, 0, 0);
  EXPECT_RGB_REL(hidden_reflection.reflected(), 0, 0, 1);
  // Behind an ior-1 window: the continued ray is a refracted image ray; reflected after it, it is both.
  const MirrorScene through_window{true, false, true};
  EXPECT_RGB_REL(through_window.direct(), 0, 0, 1);
  EXPECT_RGB_REL(through_window.reflected(), 1, 0, 0);
  const MirrorScene no_reflection_through_window{false, true, true};
  EXPECT_RGB_REL(no_reflection_through_window.direct(), 1, 0, 0);
  EXPECT_RGB_REL(no_reflection_through_window.reflected(), 0, 0, 1);
  // A no_image child of a union kept whole: seen by the camera ray, not through the window.
  const MirrorScene in_union{true, false, false, true};
  EXPECT_RGB_REL(in_union.direct(), 1, 0, 0);
  const MirrorScene in_union_through_window{true, false, true, true};
  EXPECT_RGB_REL(in_union_through_window.direct(), 0, 0, 1);
}

}  // namespace
