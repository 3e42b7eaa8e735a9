// Accelerator: closest_hit and for_each_shadow_hit against brute force over random scenes, structural invariants of
// the depth-first node layout, degenerate inputs (empty, planes only, coincident primitives, skewed
// distributions), and build time for 100,000 primitives.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "geometry_kit.hpp"
#include "renderer/geometry.hpp"

namespace povtrace::render {

// Read access to the private node layout (declared a friend in geometry.hpp).
class AcceleratorTestAccess {
 public:
  struct Summary {
    int max_depth = 0;
    std::size_t leaves = 0;
    std::vector<int> primitive_seen;  // how often each primitive index appears in a leaf
  };

  static std::size_t node_count(const Accelerator& a) { return a.nodes_.size(); }
  static std::size_t unbounded_count(const Accelerator& a) { return a.unbounded_.size(); }

  // Walks the tree checking the layout invariants with gtest assertions; returns counts for further checks.
  static Summary check(const Accelerator& a) {
    Summary s;
    s.primitive_seen.assign(a.primitives_.size(), 0);
    if (a.nodes_.empty()) return s;
    walk(a, 0, 0, s);
    return s;
  }

 private:
  // Returns one past the last node index of the subtree rooted at `node`.
  static std::uint32_t walk(const Accelerator& a, std::uint32_t node, int depth, Summary& s) {
    s.max_depth = std::max(s.max_depth, depth);
    const auto& n = a.nodes_.at(node);
    if (n.count > 0) {
      EXPECT_LE(n.count, 4u);
      ++s.leaves;
      for (std::uint32_t k = n.first; k < n.first + n.count; ++k) {
        const std::uint32_t i = a.order_.at(k);
        ++s.primitive_seen.at(i);
        const Bounds b = world_bounds(a.primitives_[i]);
        for (int c = 0; c < 3; ++c) {
          EXPECT_LE(n.bounds.lo[c], b.lo[c]);
          EXPECT_GE(n.bounds.hi[c], b.hi[c]);
        }
      }
      return node + 1;
    }
    EXPECT_LT(n.axis, 3);
    const std::uint32_t left = node + 1;
    const std::uint32_t after_left = walk(a, left, depth + 1, s);
    EXPECT_EQ(n.first, after_left) << "right child must follow the left subtree (depth-first order)";
    for (const std::uint32_t child : {left, n.first}) {
      const auto& c = a.nodes_.at(child);
      for (int k = 0; k < 3; ++k) {
        EXPECT_LE(n.bounds.lo[k], c.bounds.lo[k]);
        EXPECT_GE(n.bounds.hi[k], c.bounds.hi[k]);
      }
    }
    return walk(a, n.first, depth + 1, s);
  }
};

}  // namespace povtrace::render

namespace {

using namespace povtrace;
using namespace povtrace::render;
using namespace povtrace::test;
using Access = AcceleratorTestAccess;

// 2,000 random spheres, boxes and transformed versions of both, in a 100-unit cube, plus planes.
std::vector<Primitive> random_scene(std::mt19937& rng, int count, bool with_planes) {
  std::uniform_real_distribution<double> pos(-50, 50), rad(0.2, 3), ang(-180, 180), sc(0.3, 2.5), u(0, 1);
  std::vector<Primitive> prims;
  for (int k = 0; k < count; ++k) {
    const Vec3 c{pos(rng), pos(rng), pos(rng)};
    Primitive p;
    const double kind = u(rng);
    if (kind < 0.35) {
      p = sphere(c, rad(rng));
    } else if (kind < 0.7) {
      p = box(c, c + Vec3{rad(rng), rad(rng), rad(rng)});
    } else {
      const Matrix m = Matrix::scaling({sc(rng), sc(rng), sc(rng)}) * Matrix::rotation({ang(rng), ang(rng), ang(rng)}) *
                       Matrix::translation(c);
      p = u(rng) < 0.5 ? transformed(sphere({0, 0, 0}, rad(rng)), m)
                       : transformed(box({-1, -0.5, -0.7}, {0.8, 1, 0.6}), m);
    }
    p.casts_shadow = u(rng) > 0.15;
    p.object = static_cast<std::uint32_t>(k);
    prims.push_back(p);
  }
  if (with_planes) {
    prims.push_back(plane({0, 1, 0}, -60));
    prims.push_back(transformed(plane({1, 0, 0}, 0), Matrix::rotation({10, 20, 30}) * Matrix::translation({70, 0, 0})));
    Primitive no_shadow_plane = plane({0, 0, -1}, -80);
    no_shadow_plane.casts_shadow = false;
    prims.push_back(no_shadow_plane);
  }
  return prims;
}

Ray random_ray(std::mt19937& rng) {
  std::uniform_real_distribution<double> pos(-80, 80), u(0, 1);
  Vec3 origin{pos(rng), pos(rng), pos(rng)};
  Vec3 dir = random_unit(rng);
  if (u(rng) < 0.1) {  // axis-aligned directions exercise the infinite reciprocal in the slab test
    const int axis = static_cast<int>(u(rng) * 3) % 3;
    dir = Vec3{};
    dir[axis] = u(rng) < 0.5 ? -1 : 1;
    if (u(rng) < 0.5) origin[(axis + 1) % 3] = std::round(origin[(axis + 1) % 3]);  // in a slab plane, often
  }
  return Ray{origin, dir};
}

void expect_same(const Hit& a, const Hit& b, int k) {
  EXPECT_EQ(a.primitive, b.primitive) << "ray " << k;
  EXPECT_EQ(a.t, b.t) << "ray " << k;
}

TEST(Bvh, EmptyAndDefault) {
  const Accelerator none;
  EXPECT_FALSE(none.closest_hit({{0, 0, 0}, {0, 0, 1}}, 1e-4, 1e10).found());
  const Accelerator empty(std::vector<Primitive>{});
  EXPECT_FALSE(empty.closest_hit({{0, 0, 0}, {0, 0, 1}}, 1e-4, 1e10).found());
  int visits = 0;
  empty.for_each_shadow_hit({{0, 0, 0}, {0, 0, 1}}, 1e-3, 1e10, [&](std::uint32_t, const SurfaceHit&) { return ++visits, true; });
  EXPECT_EQ(visits, 0);
  EXPECT_TRUE(empty.primitives().empty());
  EXPECT_EQ(Access::node_count(empty), 0u);
}

TEST(Bvh, PlanesOnly) {
  const Accelerator a(std::vector<Primitive>{plane({0, 1, 0}, -1), plane({0, 1, 0}, 2)});
  EXPECT_EQ(Access::node_count(a), 0u);
  EXPECT_EQ(Access::unbounded_count(a), 2u);
  Hit h = a.closest_hit({{0, 0, 0}, {0, 1, 0}}, 1e-4, 1e10);
  ASSERT_TRUE(h.found());
  EXPECT_EQ(h.primitive, 1u);
  EXPECT_DOUBLE_EQ(h.t, 2);
  h = a.closest_hit({{0, 0, 0}, {0, -1, 0}}, 1e-4, 1e10);
  ASSERT_TRUE(h.found());
  EXPECT_EQ(h.primitive, 0u);
  EXPECT_FALSE(a.closest_hit({{0, 0, 0}, {0, 1, 0}}, 1e-4, 1.5).found());  // t_max is exclusive of farther hits
}

TEST(Bvh, SmallSceneHandChecked) {
  // Two spheres on the z axis and a box between them; the ray from the origin meets the box first.
  const Accelerator a(std::vector<Primitive>{sphere({0, 0, 10}, 1), box({-1, -1, 4}, {1, 1, 5}), sphere({0, 0, 20}, 2)});
  Hit h = a.closest_hit({{0, 0, 0}, {0, 0, 1}}, 1e-4, 1e10);
  ASSERT_TRUE(h.found());
  EXPECT_EQ(h.primitive, 1u);
  EXPECT_DOUBLE_EQ(h.t, 4);
  // Starting inside the box: the exit face.
  h = a.closest_hit({{0, 0, 4.5}, {0, 0, 1}}, 1e-4, 1e10);
  EXPECT_EQ(h.primitive, 1u);
  EXPECT_DOUBLE_EQ(h.t, 0.5);
  // t_min beyond the box and the first sphere's near side: the first sphere's far side.
  h = a.closest_hit({{0, 0, 0}, {0, 0, 1}}, 9.5, 1e10);
  EXPECT_EQ(h.primitive, 0u);
  EXPECT_DOUBLE_EQ(h.t, 11);
  // Shadow hits between 0 and 15: box (4, 5) and sphere 0 (9, 11).
  std::multiset<std::pair<std::uint32_t, double>> seen;
  a.for_each_shadow_hit({{0, 0, 0}, {0, 0, 1}}, 1e-3, 15, [&](std::uint32_t i, const SurfaceHit& s) {
    seen.insert({i, s.t});
    return true;
  });
  const std::multiset<std::pair<std::uint32_t, double>> expect{{1, 4}, {1, 5}, {0, 9}, {0, 11}};
  EXPECT_EQ(seen, expect);
}

TEST(Bvh, LayoutInvariants) {
  std::mt19937 rng(11);
  const Accelerator a(random_scene(rng, 2000, true));
  const auto s = Access::check(a);
  EXPECT_EQ(Access::unbounded_count(a), 3u);
  for (std::size_t i = 0; i < 2000; ++i) EXPECT_EQ(s.primitive_seen[i], 1) << i;
  for (std::size_t i = 2000; i < 2003; ++i) EXPECT_EQ(s.primitive_seen[i], 0) << i;
  EXPECT_LT(s.max_depth, 40);
  EXPECT_GE(s.leaves, 500u);
}

TEST(Bvh, ClosestHitMatchesBruteForce) {
  std::mt19937 rng(4242);
  const Accelerator a(random_scene(rng, 2000, true));
  std::uniform_real_distribution<double> u(0, 1);
  int found = 0;
  for (int k = 0; k < 10000; ++k) {
    const Ray r = random_ray(rng);
    const double t_min = k % 5 == 0 ? 1e-3 + 20 * u(rng) : tolerance::min_isect_depth;
    const double t_max = k % 3 == 0 ? 5 + 100 * u(rng) : tolerance::bound_huge;
    const Hit fast = a.closest_hit(r, t_min, t_max);
    const Hit slow = a.closest_hit_brute_force(r, t_min, t_max);
    expect_same(fast, slow, k);
    found += fast.found();
    if (fast.found()) {
      EXPECT_GT(fast.t, t_min);
      EXPECT_LT(fast.t, t_max);
    }
  }
  EXPECT_GT(found, 5000);
}

TEST(Bvh, ClosestHitWithoutPlanesMatchesBruteForce) {
  std::mt19937 rng(777);
  const Accelerator a(random_scene(rng, 2000, false));
  int found = 0;
  for (int k = 0; k < 10000; ++k) {
    const Ray r = random_ray(rng);
    const Hit fast = a.closest_hit(r, tolerance::min_isect_depth, tolerance::bound_huge);
    expect_same(fast, a.closest_hit_brute_force(r, tolerance::min_isect_depth, tolerance::bound_huge), k);
    found += fast.found();
  }
  EXPECT_GT(found, 1000);
}

TEST(Bvh, ShadowHitsMatchBruteForce) {
  std::mt19937 rng(8080);
  const Accelerator a(random_scene(rng, 2000, true));
  std::uniform_real_distribution<double> u(0, 1);
  std::size_t total = 0;
  for (int k = 0; k < 3000; ++k) {
    const Ray r = random_ray(rng);
    const double t_min = tolerance::shadow;
    const double t_max = k % 2 ? 200 * u(rng) : tolerance::bound_huge;
    std::multiset<std::pair<std::uint32_t, double>> fast, slow;
    a.for_each_shadow_hit(r, t_min, t_max, [&](std::uint32_t i, const SurfaceHit& h) {
      fast.insert({i, h.t});
      return true;
    });
    const auto prims = a.primitives();
    for (std::uint32_t i = 0; i < prims.size(); ++i) {
      if (!prims[i].casts_shadow) continue;
      const Intersections xs = intersect_all(prims[i], r);
      for (int j = 0; j < xs.count; ++j)
        if (xs.t[j] > t_min && xs.t[j] < t_max) slow.insert({i, xs.t[j]});
    }
    EXPECT_EQ(fast, slow) << "ray " << k;
    for (const auto& [i, t] : fast) EXPECT_TRUE(prims[i].casts_shadow);
    total += fast.size();
  }
  EXPECT_GT(total, 3000u);
}

TEST(Bvh, ShadowVisitorStopsEarly) {
  std::vector<Primitive> row;
  for (int k = 0; k < 50; ++k) row.push_back(sphere({0, 0, 3.0 * k + 5}, 1));
  const Accelerator a(row);
  int visits = 0;
  a.for_each_shadow_hit({{0, 0, 0}, {0, 0, 1}}, 1e-3, 1e9, [&](std::uint32_t, const SurfaceHit&) {
    ++visits;
    return false;
  });
  EXPECT_EQ(visits, 1);
  // Also a visitor returning void (never stops) sees all 100 crossings.
  int all = 0;
  a.for_each_shadow_hit({{0, 0, 0}, {0, 0, 1}}, 1e-3, 1e9, [&](std::uint32_t, const SurfaceHit&) { ++all; });
  EXPECT_EQ(all, 100);
  // A const visitor object works too.
  struct Counter {
    int* n;
    bool operator()(std::uint32_t, const SurfaceHit&) const { return ++*n < 7; }
  };
  int counted = 0;
  const Counter counter{&counted};
  a.for_each_shadow_hit({{0, 0, 0}, {0, 0, 1}}, 1e-3, 1e9, counter);
  EXPECT_EQ(counted, 7);
}

TEST(Bvh, NoShadowPrimitivesAreSkipped) {
  Primitive blocker = box({-1, -1, 4}, {1, 1, 5});
  blocker.casts_shadow = false;
  const Accelerator a(std::vector<Primitive>{blocker, sphere({0, 0, 10}, 1)});
  std::vector<std::uint32_t> seen;
  a.for_each_shadow_hit({{0, 0, 0}, {0, 0, 1}}, 1e-3, 100, [&](std::uint32_t i, const SurfaceHit&) {
    seen.push_back(i);
    return true;
  });
  EXPECT_EQ(seen, (std::vector<std::uint32_t>{1, 1}));
  // closest_hit still sees it (no_shadow only affects shadow rays).
  EXPECT_EQ(a.closest_hit({{0, 0, 0}, {0, 0, 1}}, 1e-4, 100).primitive, 0u);
}

TEST(Bvh, CoincidentPrimitivesTieToLowestIndex) {
  std::vector<Primitive> same(1000, sphere({1, 2, 3}, 1));
  same.push_back(sphere({1, 2, 30}, 1));
  const Accelerator a(same);
  const auto s = Access::check(a);
  EXPECT_LT(s.max_depth, 64);
  const Hit h = a.closest_hit({{1, 2, -10}, {0, 0, 1}}, 1e-4, 1e10);
  EXPECT_EQ(h.primitive, 0u);
  EXPECT_DOUBLE_EQ(h.t, 12);
  expect_same(h, a.closest_hit_brute_force({{1, 2, -10}, {0, 0, 1}}, 1e-4, 1e10), 0);
  const Hit back = a.closest_hit({{1, 2, 40}, {0, 0, -1}}, 1e-4, 1e10);
  EXPECT_EQ(back.primitive, 1000u);
}

TEST(Bvh, SkewedDistributionStaysShallow) {
  // Geometrically growing positions and sizes defeat a plain SAH; the depth cap must keep the tree within the stack.
  std::vector<Primitive> prims;
  double x = 1;
  for (int k = 0; k < 3000; ++k) {
    prims.push_back(sphere({x, 0, 0}, x * 0.01));
    x *= 1.01;
  }
  const Accelerator a(prims);
  const auto s = Access::check(a);
  EXPECT_LT(s.max_depth, 64);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0, 1);
  for (int k = 0; k < 2000; ++k) {
    const Ray r{{-10, 0.5 * u(rng) - 0.25, 0.5 * u(rng) - 0.25}, normalize(Vec3{1, 1e-4 * (u(rng) - 0.5), 1e-4 * (u(rng) - 0.5)})};
    expect_same(a.closest_hit(r, 1e-4, 1e12), a.closest_hit_brute_force(r, 1e-4, 1e12), k);
  }
}

TEST(Bvh, HundredThousandPrimitivesBuildFast) {
  std::mt19937 rng(1);
  std::vector<Primitive> prims = random_scene(rng, 100000, true);
  const auto start = std::chrono::steady_clock::now();
  const Accelerator a(std::move(prims));
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  RecordProperty("build_seconds", std::to_string(seconds));
#ifdef NDEBUG
  EXPECT_LT(seconds, 1.0);
#else
  EXPECT_LT(seconds, 10.0);
#endif
  const auto s = Access::check(a);
  EXPECT_LT(s.max_depth, 64);
  for (int k = 0; k < 300; ++k) {
    const Ray r = random_ray(rng);
    expect_same(a.closest_hit(r, 1e-4, 2e10), a.closest_hit_brute_force(r, 1e-4, 2e10), k);
  }
}

}  // namespace
