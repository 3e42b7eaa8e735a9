// Camera rays (povray-pixel-pipeline.md §1): pixel centres u = (i+0.5)/W − 0.5, v = 0.5 − (j+0.5)/H (j = 0 is the top
// row); perspective rays from the location through D + uR + vU, orthographic rays from location + uR + vU along D;
// directions are unit length.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "scene_kit.hpp"

namespace {

using namespace povtrace;
using namespace povtrace::render;
using namespace povtrace::render::test;

RenderCamera default_camera_at(Vec3 location) {
  // POV-Ray's defaults (§1): direction <0,0,1>, up <0,1,0>, right <1.33,0,0>; look_at <0,0,0> from <0,0,-5> keeps them.
  return RenderCamera{Projection::perspective, location, {0, 0, 1}, {0, 1, 0}, {1.33, 0, 0}};
}

TEST(CameraRay, DefaultCameraPixelZeroZero) {
  // §1 [V item1_camera_default]: 4×3 image, pixel (0,0): u = 0.5/4 − 0.5 = −0.375, v = 0.5 − 0.5/3 = 1/3.
  // The ray D + uR + vU = (1.33·(−0.375), 1/3, 1) from <0,0,−5> meets z = 0 at 5·(that vector).
  const RenderCamera cam = default_camera_at({0, 0, -5});
  const Ray r = *camera_ray(cam, 0, 0, 4, 3);
  EXPECT_EQ(r.origin, (Vec3{0, 0, -5}));
  EXPECT_REL(length(r.direction), 1.0);
  const double t = 5.0 / r.direction.z;
  const Vec3 p = r.origin + r.direction * t;
  EXPECT_REL(p.x, 5 * 1.33 * -0.375);
  EXPECT_REL(p.y, 5.0 / 3.0);
  EXPECT_NEAR(p.z, 0.0, 1e-12);
  // The verified pixel value of the item1 scene: red = (x + 4)/8 = 0.18828, green = (y + 4)/8 = 0.70833.
  EXPECT_NEAR((p.x + 4) / 8, 0.18828, 5e-6);
  EXPECT_NEAR((p.y + 4) / 8, 0.70833, 5e-6);
}

TEST(CameraRay, PerspectiveEveryPixelCentre) {
  const RenderCamera cam = default_camera_at({1, 2, -5});
  const int W = 5, H = 3;
  for (int j = 0; j < H; ++j)
    for (int i = 0; i < W; ++i) {
      const double u = (i + 0.5) / W - 0.5, v = 0.5 - (j + 0.5) / H;
      const Vec3 expected = normalize(Vec3{0, 0, 1} + Vec3{1.33, 0, 0} * u + Vec3{0, 1, 0} * v);
      const Ray r = *camera_ray(cam, i, j, W, H);
      EXPECT_EQ(r.origin, (Vec3{1, 2, -5}));
      EXPECT_REL(length(r.direction), 1.0);
      EXPECT_REL(r.direction.x, expected.x);
      EXPECT_REL(r.direction.y, expected.y);
      EXPECT_REL(r.direction.z, expected.z);
    }
  // The centre of an odd-sized image looks straight along D.
  const Ray centre = *camera_ray(cam, 2, 1, W, H);
  EXPECT_NEAR(centre.direction.x, 0.0, 1e-15);
  EXPECT_NEAR(centre.direction.y, 0.0, 1e-15);
  EXPECT_REL(centre.direction.z, 1.0);
}

TEST(CameraRay, PerspectiveLongDirectionNarrowsTheView) {
  // |D| = 2 (as after `angle`), R = 4x, U = 3y: pixel (0,0) of 2×2 → u = −0.25, v = 0.25 → (−1, 0.75, 2)/|…|.
  const RenderCamera cam{Projection::perspective, {0, 0, 0}, {0, 0, 2}, {0, 3, 0}, {4, 0, 0}};
  const Ray r = *camera_ray(cam, 0, 0, 2, 2);
  const double n = std::sqrt(1 + 0.75 * 0.75 + 4);
  EXPECT_REL(r.direction.x, -1 / n);
  EXPECT_REL(r.direction.y, 0.75 / n);
  EXPECT_REL(r.direction.z, 2 / n);
}

TEST(CameraRay, OrthographicOriginsOnTheImagePlane) {
  // §1: origin = location + uR + vU, direction = normalise(D) even when |D| ≠ 1.
  const RenderCamera cam{Projection::orthographic, {1, -1, -10}, {0, 0, 3}, {0, 4, 0}, {8, 0, 0}};
  const int W = 4, H = 2;
  for (int j = 0; j < H; ++j)
    for (int i = 0; i < W; ++i) {
      const double u = (i + 0.5) / W - 0.5, v = 0.5 - (j + 0.5) / H;
      const Ray r = *camera_ray(cam, i, j, W, H);
      EXPECT_REL(r.origin.x, 1 + 8 * u);
      EXPECT_REL(r.origin.y, -1 + 4 * v);
      EXPECT_REL(r.origin.z, -10.0);
      EXPECT_EQ(r.direction, (Vec3{0, 0, 1}));
    }
  // Pixel (0,0): u = 0.125 − 0.5 = −0.375 → x = 1 − 3 = −2; v = 0.5 − 0.25 = 0.25 → y = −1 + 1 = 0.
  const Ray r = *camera_ray(cam, 0, 0, W, H);
  EXPECT_REL(r.origin.x, -2.0);
  EXPECT_NEAR(r.origin.y, 0.0, 1e-15);
}

TEST(CameraRay, ContinuousSubSamplePositions) {
  // A sub-sample at (x, y) = (1.25, 0.75) of a 4×4 image: u = 1.75/4 − 0.5 = −0.0625, v = 0.5 − 1.25/4 = 0.1875.
  const RenderCamera ortho{Projection::orthographic, {0, 0, -10}, {0, 0, 1}, {0, 4, 0}, {4, 0, 0}};
  const Ray r = *camera_ray(ortho, 1.25, 0.75, 4, 4);
  EXPECT_REL(r.origin.x, 4 * -0.0625);
  EXPECT_REL(r.origin.y, 4 * 0.1875);
  // Pixel corners (x ± ½) land exactly on pixel boundaries: x = −0.5 is the image's left edge u = −0.5.
  const Ray corner = *camera_ray(ortho, -0.5, -0.5, 4, 4);
  EXPECT_REL(corner.origin.x, -2.0);
  EXPECT_REL(corner.origin.y, 2.0);
}

TEST(CameraRay, RightHandedRightMirrorsTheImage) {
  // right −1.33x (§1 "mirrored image"): pixel 0 now looks toward +x.
  const RenderCamera cam{Projection::perspective, {0, 0, -5}, {0, 0, 1}, {0, 1, 0}, {-1.33, 0, 0}};
  const Ray r = *camera_ray(cam, 0, 1, 4, 3);
  EXPECT_GT(r.direction.x, 0.0);
  EXPECT_REL(r.direction.x / r.direction.z, -1.33 * -0.375);
}

TEST(CameraRender, TopRowIsPositiveYLeftColumnIsNegativeX) {
  // A white ambient box over the top-left quadrant of a 2×2 orthographic view: only pixel (0,0) is white.
  SceneDescription s = base_scene();
  s.objects.push_back(box_object({-3, 0, -1}, {0, 3, 1}, texture(rgb(1, 1, 1), finish_ambient_diffuse(1, 0))));
  const RenderScene rs = build_render_scene(s, BuildOptions{});
  RenderSettings settings;
  settings.width = 2;
  settings.height = 2;
  settings.threads = 1;
  const RenderResult out = povtrace::render::render(rs, settings);
  EXPECT_EQ(out.image.pixel(0, 0)[0], 1.0f);
  EXPECT_EQ(out.image.pixel(1, 0)[0], 0.0f);
  EXPECT_EQ(out.image.pixel(0, 1)[0], 0.0f);
  EXPECT_EQ(out.image.pixel(1, 1)[0], 0.0f);
  EXPECT_EQ(out.image.pixel(0, 0)[3], 1.0f);
  EXPECT_EQ(out.rays.camera, 4u);
}

}  // namespace

// ---- The non-planar projections (renderer/camera.cpp, POV-Ray's CreateCameraRay) ------------------------------

namespace {
RenderCamera projection_camera(Projection p, double angle, Vec3 up = {0, 1, 0}, Vec3 right = {1.33, 0, 0}) {
  Camera c;
  c.projection = p;
  c.location = {0, 0, 0};
  c.direction = {0, 0, 2};
  c.up = up;
  c.right = right;
  c.angle = angle;
  return make_render_camera(c);
}
double degrees_between(Vec3 a, Vec3 b) { return std::acos(std::clamp(dot(normalize(a), normalize(b)), -1.0, 1.0)) * 180 / M_PI; }
}  // namespace

// POV-Ray's SetupCamera normalises the non-planar cameras' vectors without turning a zero vector into NaN: a fisheye
// with `direction 0` looks sideways, along right and up. A pixel whose ray has no direction gets no ray.
TEST(CameraProjections, ZeroVectorsStayZeroAndNoRayIsNaN) {
  Camera c;
  c.projection = Projection::fisheye;
  c.direction = {0, 0, 0};
  const RenderCamera cam = make_render_camera(c);
  std::size_t traced = 0;
  for (int y = 0; y < 24; ++y)
    for (int x = 0; x < 32; ++x)
      if (const std::optional<Ray> r = camera_ray(cam, x, y, 32, 24)) {
        ++traced;
        EXPECT_TRUE(std::isfinite(r->direction.x) && std::isfinite(r->direction.y) && std::isfinite(r->direction.z));
        EXPECT_NEAR(length(r->direction), 1.0, 1e-12);
        EXPECT_NEAR(r->direction.z, 0.0, 1e-12);
      }
  EXPECT_GT(traced, 300u);
  // Perspective with direction 0 on an odd image: the centre pixel's ray D + uR + vU is zero.
  RenderCamera p{Projection::perspective, {0, 0, 0}, {0, 0, 0}, {0, 1, 0}, {1.33, 0, 0}};
  EXPECT_FALSE(camera_ray(p, 1, 1, 3, 3).has_value());
  ASSERT_TRUE(camera_ray(p, 0, 1, 3, 3).has_value());
}

TEST(CameraProjections, FisheyeMapsRadiusToHalfTheAngle) {
  // 100×100 pixels, right and up of length 1: x = 74.5 gives u = 75/100 − ½ = ¼, so a radius 2u = ½, which is
  // ½ · 180°/2 = 45° off the axis for `angle 180`, turned towards +right.
  const RenderCamera cam = projection_camera(Projection::fisheye, 180, {0, 1, 0}, {1, 0, 0});
  const Ray centre = *camera_ray(cam, 49.5, 49.5, 100, 100);
  EXPECT_NEAR(degrees_between(centre.direction, {0, 0, 1}), 0.0, 1e-9);
  const Ray side = *camera_ray(cam, 74.5, 49.5, 100, 100);
  EXPECT_NEAR(degrees_between(side.direction, {0, 0, 1}), 45.0, 1e-9);
  EXPECT_GT(side.direction.x, 0.0);
  EXPECT_FALSE(camera_ray(cam, 0, 0, 100, 100).has_value());   // a corner lies outside the circle
}

TEST(CameraProjections, CylinderOneTurnsHorizontallyAndStepsVertically) {
  // cylinder 1, angle 120: u = ±½ turns ±60° about up; v moves along up by v·|up|.
  const RenderCamera cam = projection_camera(Projection::cylinder1, 120, {0, 2, 0});
  const Ray right_edge = *camera_ray(cam, 99.5, 49.5, 100, 100);
  EXPECT_NEAR(std::atan2(right_edge.direction.x, right_edge.direction.z) * 180 / M_PI, 60.0, 1e-9);
  const Ray top = *camera_ray(cam, 49.5, -0.5, 100, 100);   // v = ½: direction (0, ½·2, 1)
  EXPECT_NEAR(top.direction.y / top.direction.z, 1.0, 1e-12);
}

TEST(CameraProjections, CylinderThreeMovesTheOriginAlongUp) {
  const RenderCamera cam = projection_camera(Projection::cylinder3, 90, {0, 3, 0});
  EXPECT_TRUE(origins_vary(cam));
  const Ray top = *camera_ray(cam, 49.5, -0.5, 100, 100);
  EXPECT_NEAR(top.origin.y, 1.5, 1e-12);
  EXPECT_NEAR(top.direction.y, 0.0, 1e-12);
}

TEST(CameraProjections, SphericalCoversItsAngles) {
  Camera c;
  c.projection = Projection::spherical;
  c.direction = {0, 0, 1};
  c.h_angle = 360;
  c.v_angle = 180;
  const RenderCamera cam = make_render_camera(c);
  // u = ½ is half of 360° round the up axis: straight behind; v = ½ is 90° up.
  EXPECT_NEAR(degrees_between(camera_ray(cam, 99.5, 49.5, 100, 100)->direction, {0, 0, -1}), 0.0, 1e-6);
  EXPECT_NEAR(degrees_between(camera_ray(cam, 49.5, -0.5, 100, 100)->direction, {0, 1, 0}), 0.0, 1e-6);
}

TEST(CameraProjections, PanoramicLooksRightAtTheLeftEdge) {
  // x0 = (1 − x/W)·π: the left edge (x/W = 0) looks along +right·cos π... i.e. −right; the middle along direction.
  const RenderCamera cam = projection_camera(Projection::panoramic, 90);
  EXPECT_NEAR(degrees_between(camera_ray(cam, 49.5, 49.5, 100, 100)->direction, {0, 0, 1}), 0.0, 1e-9);
  EXPECT_NEAR(degrees_between(camera_ray(cam, -0.5, 49.5, 100, 100)->direction, {-1, 0, 0}), 0.0, 1e-9);
}
