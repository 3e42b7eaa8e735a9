// Meshes: the per-mesh BVH against brute force over the triangles, watertightness on a closed icosphere (rays
// aimed exactly at shared vertices and edges never leak), placements of one shared mesh against the same
// triangles placed one by one, and inside_vector.
#include <gtest/gtest.h>
#include <optional>

#include "renderer/shapes/watertight.hpp"
#include "tests/geometry/mesh_kit.hpp"

namespace povtrace::test {
namespace {

// Nearest hit over every triangle of the mesh, in the same object space and with the same rules as the BVH walk.
bool brute_force_nearest(const MeshData& d, const render::Ray& object_ray, double& t) {
  const render::shapes::ShearedRay sheared(object_ray);
  bool found = false;
  t = 1e7;
  for (std::size_t i = 0; i < d.triangle_count(); ++i) {
    render::shapes::TriangleHit h;
    if (!render::shapes::intersect_watertight(sheared, d.vertex(d.faces[3 * i]), d.vertex(d.faces[3 * i + 1]),
                                              d.vertex(d.faces[3 * i + 2]), h))
      continue;
    if (h.t >= 1e-6 && h.t <= 1e7 && h.t < t) {
      t = h.t;
      found = true;
    }
  }
  return found;
}

TEST(Mesh, BvhNearestHitEqualsBruteForce) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.5, 1.5);
  // A bumpy sphere: the icosphere's vertices pushed in and out, so triangles overlap in depth.
  auto sphere = icosphere(3);
  auto bumpy = std::make_shared<MeshData>(*sphere);
  for (float& c : bumpy->vertices) c *= static_cast<float>(1.0 + 0.1 * u(rng));
  const render::Primitive p = mesh(bumpy);
  int hits = 0;
  for (int i = 0; i < 5000; ++i) {
    const Vec3 origin{u(rng) * 2, u(rng) * 2, u(rng) * 2};
    const render::Ray r = ray(origin, random_unit(rng) * 0.9 - origin);   // aimed into the sphere
    double expected = 0;
    const bool found = brute_force_nearest(*bumpy, r, expected);
    const std::optional<render::SurfaceHit> hit = render::nearest_hit(p, r, 0.0, 1e10);
    ASSERT_EQ(hit.has_value(), found) << "ray " << i;
    if (!found) continue;
    EXPECT_EQ(hit->t, expected) << "ray " << i;
    ++hits;
    render::HitBuffer all;
    render::collect_hits(p, r, all);
    EXPECT_GE(all.size(), 1u);
  }
  EXPECT_GT(hits, 2000);
}

TEST(Mesh, RaysAtSharedVerticesAndEdgesOfAClosedMeshNeverLeak) {
  const auto sphere = icosphere(2);
  const MeshData& d = *sphere;
  std::vector<Vec3> targets;
  for (std::uint32_t v = 0; v < d.vertices.size() / 3; ++v) targets.push_back(d.vertex(v));
  for (std::size_t i = 0; i < d.faces.size(); i += 3)
    for (int k = 0; k < 3; ++k) {
      const Vec3 a = d.vertex(d.faces[i + k]), b = d.vertex(d.faces[i + (k + 1) % 3]);
      targets.push_back((a + b) * 0.5);                  // edge midpoint
      targets.push_back(a + (b - a) * (1.0 / 3.0));      // another point on the edge
    }
  std::mt19937 rng(5);
  for (const Matrix& m : {Matrix::identity(), random_transform(rng), random_transform(rng)}) {
    render::Primitive p = mesh(sphere);
    p.transformed = !(m == Matrix::identity());
    p.world_from_object = m;
    p.object_from_world = m.inverse();
    int rays = 0;
    for (const Vec3& target : targets) {
      const Vec3 world_target = m.point(target);
      // From the centre outwards, and from outside inwards through the same point.
      const Vec3 centre = m.point({0, 0, 0});
      const render::Ray out{centre, normalize(world_target - centre)};
      const render::Ray in{world_target + (world_target - centre) * 2.0, normalize(centre - world_target)};
      std::optional<render::SurfaceHit> hit;
      hit = render::nearest_hit(p, out, 0.0, 1e10);
      EXPECT_TRUE(hit) << "outward ray leaked at target " << rays;
      hit = render::nearest_hit(p, in, 0.0, 1e10);
      EXPECT_TRUE(hit) << "inward ray leaked at target " << rays;
      ++rays;
    }
    for (int i = 0; i < 20000; ++i) {   // every ray from inside a closed mesh hits it
      const std::optional<render::SurfaceHit> hit =
          render::nearest_hit(p, render::Ray{m.point({0.01, -0.02, 0.03}), random_unit(rng)}, 0.0, 1e10);
      ASSERT_TRUE(hit);
    }
  }
}

TEST(Mesh, PlacementsOfASharedMeshEqualTheSameTrianglesPlacedOneByOne) {
  std::mt19937 rng(3);
  const auto sphere = icosphere(1);
  const MeshData& d = *sphere;
  for (int placement = 0; placement < 4; ++placement) {
    const Matrix m = random_transform(rng);
    render::Primitive instance = mesh(sphere);
    instance.transformed = true;
    instance.world_from_object = m;
    instance.object_from_world = m.inverse();
    std::vector<render::Primitive> singles;
    for (std::size_t i = 0; i < d.faces.size(); i += 3)
      singles.push_back(triangle(d.vertex(d.faces[i]), d.vertex(d.faces[i + 1]), d.vertex(d.faces[i + 2]), m));
    const render::Accelerator individual(singles);
    int mismatched = 0, hits = 0;
    for (int i = 0; i < 3000; ++i) {
      const Vec3 origin = m.point(random_unit(rng) * 4.0);
      const render::Ray aimed{origin, normalize(m.point(random_unit(rng) * 1.05) - origin)};
      const std::optional<render::SurfaceHit> hit = render::nearest_hit(instance, aimed, 1e-4, 1e10);
      const bool found = hit.has_value();
      const render::Hit expected = individual.closest_hit(aimed, 1e-4, 1e10);
      if (found != expected.found()) { ++mismatched; continue; }   // grazing a silhouette edge: either answer
      if (!found) continue;
      ++hits;
      EXPECT_NEAR(hit->t, expected.t, 1e-9 * expected.t);
      const Vec3 at = aimed.origin + aimed.direction * hit->t;
      EXPECT_NEAR(std::fabs(dot(render::surface_normal(*hit, at),
                                render::surface_normal(expected.surface, at))), 1.0, 1e-9);
    }
    EXPECT_LE(mismatched, 3);
    EXPECT_GT(hits, 1000);
  }
}

TEST(Mesh, InsideFollowsInsideVectorParity) {
  auto data = std::make_shared<MeshData>(*icosphere(2));
  const render::Primitive open = mesh(data);
  EXPECT_FALSE(render::inside(open, {0, 0, 0}));   // no inside_vector: nothing is inside
  auto closed = std::make_shared<MeshData>(*data);
  closed->inside_vector = normalize(Vec3{0.3, 0.2, 1});
  render::Primitive p = mesh(closed);
  EXPECT_TRUE(render::inside(p, {0.1, 0.2, -0.1}));
  EXPECT_FALSE(render::inside(p, {2, 0, 0}));
  p.inverse = true;
  EXPECT_FALSE(render::inside(p, {0.1, 0.2, -0.1}));
}

}  // namespace
}  // namespace povtrace::test

namespace povtrace::test {
namespace {

// Embree picks the nearest triangle in single precision and the exact test measures it (accel/embree_mesh.hpp):
// the same hits as the own walk, at the exact depth of the triangle picked; only triangles within rounding of
// each other in depth may be picked differently.
TEST(EmbreeMesh, NearestHitEqualsTheOwnWalk) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.5, 1.5);
  auto bumpy = std::make_shared<MeshData>(*icosphere(3));
  for (float& c : bumpy->vertices) c *= static_cast<float>(1.0 + 0.1 * u(rng));
  const render::Primitive own = mesh(bumpy);
  render::Primitive fast = mesh(bumpy);
  render::shapes::prepare_embree_mesh(fast);
  ASSERT_TRUE(fast.embree_nearest);
  int hits = 0, same_triangle = 0;
  for (int i = 0; i < 5000; ++i) {
    const Vec3 origin{u(rng) * 2, u(rng) * 2, u(rng) * 2};
    const render::Ray r = ray(origin, random_unit(rng) * 0.9 - origin);
    std::optional<render::SurfaceHit> a, b;
    a = render::nearest_hit(own, r, 0.0, 1e10);
    const bool found = a.has_value();
    b = render::nearest_hit(fast, r, 0.0, 1e10);
    ASSERT_EQ(b.has_value(), found) << "ray " << i;
    if (!found) continue;
    ++hits;
    EXPECT_NEAR(b->t, a->t, 1e-6 * a->t) << "ray " << i;
    same_triangle += a->element == b->element && a->t == b->t;
  }
  EXPECT_GT(hits, 2000);
  EXPECT_GE(same_triangle, hits * 99 / 100);
}

TEST(EmbreeMesh, RaysThroughSharedEdgesOfAClosedMeshNeverLeak) {
  const auto sphere = icosphere(2);
  const MeshData& d = *sphere;
  std::mt19937 rng(5);
  render::Primitive p = mesh(sphere);
  render::shapes::prepare_embree_mesh(p);
  ASSERT_TRUE(p.embree_nearest);
  for (std::size_t i = 0; i < d.faces.size(); i += 3)
    for (int k = 0; k < 3; ++k) {
      const Vec3 a = d.vertex(d.faces[i + k]), b = d.vertex(d.faces[i + (k + 1) % 3]);
      for (const Vec3 target : {a, (a + b) * 0.5, a + (b - a) * (1.0 / 3.0)}) {
        std::optional<render::SurfaceHit> hit;
        hit = render::nearest_hit(p, render::Ray{{0, 0, 0}, normalize(target)}, 0.0, 1e10);
        EXPECT_TRUE(hit);
        hit = render::nearest_hit(p, render::Ray{target * 3.0, normalize(-target)}, 0.0, 1e10);
        EXPECT_TRUE(hit);
      }
    }
  for (int i = 0; i < 20000; ++i) {
    const std::optional<render::SurfaceHit> hit =
        render::nearest_hit(p, render::Ray{{0.01, -0.02, 0.03}, random_unit(rng)}, 0.0, 1e10);
    ASSERT_TRUE(hit);
  }
}

}  // namespace
}  // namespace povtrace::test
