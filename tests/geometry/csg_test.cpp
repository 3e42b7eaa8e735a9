// CSG nodes (renderer/shapes/csg.cpp): random boolean trees of spheres, boxes and planes checked against an
// independent evaluation — the tree's inside/outside classified with the shapes' implicit functions, marched along
// the ray, its sign changes bisected — plus the rules that marching cannot see (union keeps internal surfaces,
// cut faces carry the subtracted object), clipped_by, bounded_by, shadow crossings and the BVH over CSG nodes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <random>
#include <vector>

#include "geometry_kit.hpp"
#include "renderer/geometry.hpp"
#include "renderer/shapes/csg.hpp"

namespace {

using namespace povtrace;
using namespace povtrace::render;
using namespace povtrace::test;

// ---- An independent model of a CSG tree ------------------------------------------------------------------------

// Implicit value of a leaf at a world point: negative inside (before `inverse`).
double implicit(const Primitive& p, Vec3 world) {
  const Vec3 q = p.transformed ? p.object_from_world.point(world) : world;
  switch (p.type) {
    case ShapeType::sphere: return length(q - p.a) - p.radius;
    case ShapeType::box: {
      double outside = -1e300;
      for (int i = 0; i < 3; ++i) outside = std::max({outside, p.a[i] - q[i], q[i] - p.b[i]});
      return outside;
    }
    case ShapeType::plane: return dot(p.a, q) - p.radius;
    default: return 0;
  }
}

struct Expr {
  enum Kind { leaf, merge, intersection, difference, union_, inverse } kind = leaf;
  Primitive shape;            // leaf
  std::vector<Expr> operands;

  bool contains(Vec3 x) const {
    switch (kind) {
      case leaf: return (implicit(shape, x) < 0) != shape.inverse;
      case union_:
      case merge: return std::any_of(operands.begin(), operands.end(), [&](const Expr& e) { return e.contains(x); });
      case intersection:
        return std::all_of(operands.begin(), operands.end(), [&](const Expr& e) { return e.contains(x); });
      case difference:
        if (!operands[0].contains(x)) return false;
        return std::none_of(operands.begin() + 1, operands.end(), [&](const Expr& e) { return e.contains(x); });
      case inverse: return !operands[0].contains(x);
    }
    return false;
  }

  // The render primitive, built with the renderer's own construction rules.
  Primitive build() const {
    std::vector<Primitive> kids;
    for (std::size_t i = 0; i < operands.size(); ++i) {
      Primitive k = operands[i].build();
      kids.push_back(kind == difference && i > 0 ? inverted(k) : k);
    }
    switch (kind) {
      case leaf: return shape;
      case union_: return make_csg(CsgOperation::union_, kids);
      case merge: return make_csg(CsgOperation::merge, kids);
      case intersection:
      case difference: return make_csg(CsgOperation::intersection, kids);
      case inverse: return inverted(kids[0]);
    }
    return shape;
  }

  void leaves(std::vector<Primitive>& out) const {
    if (kind == leaf) out.push_back(shape);
    for (const Expr& e : operands) e.leaves(out);
  }
};

Expr leaf_of(Primitive p) { return Expr{Expr::leaf, p, {}}; }

// The same tree with every leaf translated by `by`.
Expr moved(Expr e, Vec3 by) {
  if (e.kind == Expr::leaf) {
    const bool inverse = e.shape.inverse;
    const Matrix m = e.shape.transformed ? e.shape.world_from_object : Matrix::identity();
    e.shape = transformed(e.shape, m * Matrix::translation(by));
    e.shape.inverse = inverse;
  }
  for (Expr& o : e.operands) o = moved(std::move(o), by);
  return e;
}
Expr node(Expr::Kind k, std::vector<Expr> operands) { return Expr{k, {}, std::move(operands)}; }

Primitive random_leaf(std::mt19937& rng, bool allow_plane) {
  std::uniform_real_distribution<double> pos(-1.5, 1.5), size(0.6, 1.8), coin(0, 1);
  Primitive p;
  const double pick = coin(rng);
  if (allow_plane && pick < 0.15) {
    p = plane(random_unit(rng), pos(rng) * 0.5);
  } else if (pick < 0.55) {
    p = sphere({pos(rng), pos(rng), pos(rng)}, size(rng));
  } else {
    const Vec3 c{pos(rng), pos(rng), pos(rng)};
    const Vec3 h{size(rng), size(rng), size(rng)};
    p = box(c - h * 0.7, c + h * 0.7);
  }
  if (p.type != ShapeType::plane && coin(rng) < 0.4) {
    const Matrix m = Matrix::scaling({size(rng), size(rng), size(rng)}) *
                     Matrix::rotation({pos(rng) * 60, pos(rng) * 60, pos(rng) * 60});
    p = transformed(p, m);
  }
  p.inverse = coin(rng) < 0.15;
  return p;
}

// A random tree of merges, intersections, differences and inversions (no unions: their internal surfaces are not
// sign changes of the solid, and are tested separately) with 2–3 operands per node.
Expr random_tree(std::mt19937& rng, int depth) {
  std::uniform_real_distribution<double> coin(0, 1);
  if (depth == 0 || coin(rng) < 0.3) return leaf_of(random_leaf(rng, true));
  static const Expr::Kind kinds[] = {Expr::merge, Expr::intersection, Expr::difference};
  const Expr::Kind k = kinds[std::uniform_int_distribution<int>(0, 2)(rng)];
  std::vector<Expr> operands;
  const int n = coin(rng) < 0.6 ? 2 : 3;
  for (int i = 0; i < n; ++i) operands.push_back(random_tree(rng, depth - 1));
  Expr e = node(k, std::move(operands));
  if (coin(rng) < 0.2) e = node(Expr::inverse, {std::move(e)});
  return e;
}

// Sign changes of the tree's solid along the ray in (0, t_end): marched in `step`s, each change bisected.
std::vector<double> marched_boundary(const Expr& e, const Ray& r, double t_end, double step) {
  std::vector<double> roots;
  auto in = [&](double t) { return e.contains(r.origin + r.direction * t); };
  double t0 = 0;
  bool in0 = in(0);
  for (double t1 = step; t1 < t_end; t1 += step) {
    const bool in1 = in(t1);
    if (in1 != in0) {
      double lo = t0, hi = t1;
      for (int it = 0; it < 60; ++it) {
        const double m = 0.5 * (lo + hi);
        if (in(m) == in0) lo = m; else hi = m;
      }
      roots.push_back(0.5 * (lo + hi));
    }
    t0 = t1;
    in0 = in1;
  }
  return roots;
}

std::vector<double> sorted_depths(const Primitive& p, const Ray& r) {
  HitBuffer hits;
  collect_hits(p, r, hits);
  std::vector<double> t;
  for (const SurfaceHit& h : hits) t.push_back(h.t);
  std::sort(t.begin(), t.end());
  return t;
}

// True when two leaf surfaces cross the ray closer than `gap` (the marching step cannot resolve that) or a leaf is
// grazed; such rays are skipped.
bool ambiguous(const Expr& e, const Ray& r, double gap) {
  std::vector<Primitive> leaves;
  e.leaves(leaves);
  std::vector<double> all;
  for (const Primitive& p : leaves) {
    const Intersections xs = intersect_all(p, r);
    for (int k = 0; k < xs.count; ++k) all.push_back(xs.t[k]);
  }
  std::sort(all.begin(), all.end());
  for (std::size_t k = 0; k + 1 < all.size(); ++k)
    if (all[k + 1] - all[k] < gap) return true;
  return false;
}

Ray random_ray_at_origin(std::mt19937& rng) {
  std::uniform_real_distribution<double> jitter(-2.5, 2.5);
  const Vec3 origin = random_unit(rng) * 10.0;
  return ray(origin, Vec3{jitter(rng), jitter(rng), jitter(rng)} - origin);
}

// ---- Random trees against the marched boolean solid ------------------------------------------------------------

TEST(Csg, RandomTreesMatchTheMarchedSolid) {
  std::mt19937 rng(4242);
  int compared = 0, with_hits = 0;
  for (int tree = 0; tree < 60; ++tree) {
    const Expr e = random_tree(rng, 3);
    const Primitive p = e.build();
    for (int k = 0; k < 40; ++k) {
      const Ray r = random_ray_at_origin(rng);
      if (ambiguous(e, r, 0.03)) continue;
      // The march covers t < 25; a plane nearly parallel to the ray can give a boundary much further out, which
      // is left out of both lists.
      const double t_end = 25.0;
      const std::vector<double> expected = marched_boundary(e, r, t_end, 0.01);
      std::vector<double> got = sorted_depths(p, r);
      got.erase(std::find_if(got.begin(), got.end(), [&](double t) { return t >= t_end; }), got.end());
      ++compared;
      with_hits += !expected.empty();
      ASSERT_EQ(got.size(), expected.size()) << "tree " << tree << " ray " << k;
      for (std::size_t i = 0; i < got.size(); ++i) EXPECT_NEAR(got[i], expected[i], 1e-9);
      const std::optional<SurfaceHit> nearest = nearest_hit(p, r, tolerance::min_isect_depth, t_end);
      ASSERT_EQ(nearest.has_value(), !got.empty());
      if (!got.empty()) {
        EXPECT_EQ(nearest->t, got[0]);
        ASSERT_NE(nearest->leaf, nullptr);
        EXPECT_NE(nearest->leaf->type, ShapeType::csg);
      }
    }
  }
  EXPECT_GT(compared, 1500);
  EXPECT_GT(with_hits, 500);
}

TEST(Csg, InsideMatchesTheModelEverywhere) {
  std::mt19937 rng(77);
  std::uniform_real_distribution<double> pos(-4, 4);
  int inside_count = 0;
  for (int tree = 0; tree < 60; ++tree) {
    const Expr e = random_tree(rng, 3);
    const Primitive p = e.build();
    for (int k = 0; k < 300; ++k) {
      const Vec3 x{pos(rng), pos(rng), pos(rng)};
      const bool expected = e.contains(x);
      inside_count += expected;
      ASSERT_EQ(inside(p, x), expected) << "tree " << tree << " point " << k;
    }
  }
  EXPECT_GT(inside_count, 1000);
}

TEST(Csg, BoundsEncloseEveryHit) {
  std::mt19937 rng(9);
  for (int tree = 0; tree < 60; ++tree) {
    const Expr e = random_tree(rng, 3);
    const Primitive p = e.build();
    const Bounds b = world_bounds(p);
    if (!b.finite()) continue;
    for (int k = 0; k < 40; ++k) {
      const Ray r = random_ray_at_origin(rng);
      HitBuffer hits;
      collect_hits(p, r, hits);
      for (const SurfaceHit& h : hits) {
        // The hit point is rebuilt from its depth, which carries a rounding error of a few ulps of the coordinates.
        const Vec3 x = r.origin + r.direction * h.t;
        for (int i = 0; i < 3; ++i) {
          const double slack = 1e-12 * (1.0 + std::abs(x[i]));
          EXPECT_GE(x[i], b.lo[i] - slack);
          EXPECT_LE(x[i], b.hi[i] + slack);
        }
      }
    }
  }
}

// ---- Rules the solid alone does not show -------------------------------------------------------------------------

TEST(Csg, UnionKeepsEveryChildHitEvenInsideAnIntersection) {
  // Two overlapping spheres in a union, intersected with a big box: all four crossings survive.
  const Primitive u = make_csg(CsgOperation::union_, {sphere({-0.5, 0, 0}, 1), sphere({0.5, 0, 0}, 1)});
  const Primitive i = make_csg(CsgOperation::intersection, {u, box({-5, -5, -5}, {5, 5, 5})});
  const std::vector<double> t = sorted_depths(i, ray({-10, 0, 0}, {1, 0, 0}));
  ASSERT_EQ(t.size(), 4u);
  EXPECT_DOUBLE_EQ(t[0], 8.5);
  EXPECT_DOUBLE_EQ(t[1], 9.5);
  EXPECT_DOUBLE_EQ(t[2], 10.5);
  EXPECT_DOUBLE_EQ(t[3], 11.5);
  // A merge of the same spheres keeps only the outer two.
  const Primitive m = make_csg(CsgOperation::merge, {sphere({-0.5, 0, 0}, 1), sphere({0.5, 0, 0}, 1)});
  const std::vector<double> tm = sorted_depths(m, ray({-10, 0, 0}, {1, 0, 0}));
  ASSERT_EQ(tm.size(), 2u);
  EXPECT_DOUBLE_EQ(tm[0], 8.5);
  EXPECT_DOUBLE_EQ(tm[1], 11.5);
}

TEST(Csg, CutFacesCarryTheSubtractedObject) {
  // difference { box { -1, 1 } sphere { <0,0,-1>, 0.5 } }: looking along +z at the centre, the first surface is
  // the inside of the sphere, inverted, with the sphere's material.
  Primitive cube = box({-1, -1, -1}, {1, 1, 1});
  cube.material = 1;
  Primitive cutter = sphere({0, 0, -1}, 0.5);
  cutter.material = 2;
  const Primitive d = make_csg(CsgOperation::intersection, {cube, inverted(cutter)});
  std::optional<SurfaceHit> h;
  h = nearest_hit(d, ray({0, 0, -5}, {0, 0, 1}), tolerance::min_isect_depth, tolerance::bound_huge);
  ASSERT_TRUE(h);
  EXPECT_DOUBLE_EQ(h->t, 4.5);
  ASSERT_NE(h->leaf, nullptr);
  EXPECT_EQ(h->leaf->material, 2u);
  EXPECT_TRUE(h->leaf->inverse);
  // The leaf's own normal at the bottom of the dent: the sphere's outward normal, +z.
  const Vec3 n = surface_normal(*h, {0, 0, -0.5});
  EXPECT_DOUBLE_EQ(n.z, 1.0);
  // Off the dent, the box face with the box's material.
  h = nearest_hit(d, ray({0.8, 0.8, -5}, {0, 0, 1}), tolerance::min_isect_depth, tolerance::bound_huge);
  ASSERT_TRUE(h);
  EXPECT_DOUBLE_EQ(h->t, 4.0);
  EXPECT_EQ(h->leaf->material, 1u);
  EXPECT_FALSE(h->leaf->inverse);
}

TEST(Csg, InverseFollowsDeMorgan) {
  const Primitive a = sphere({-0.5, 0, 0}, 1), b = sphere({0.5, 0, 0}, 1);
  const Primitive inv_union = inverted(make_csg(CsgOperation::union_, {a, b}));
  EXPECT_EQ(static_cast<const CsgData&>(*inv_union.data).operation, CsgOperation::intersection);
  const Primitive inv_inter = inverted(make_csg(CsgOperation::intersection, {a, b}));
  EXPECT_EQ(static_cast<const CsgData&>(*inv_inter.data).operation, CsgOperation::merge);
  for (const Primitive& child : static_cast<const CsgData&>(*inv_inter.data).children) EXPECT_TRUE(child.inverse);
  EXPECT_FALSE(inside(inv_union, {0, 0, 0}));
  EXPECT_TRUE(inside(inv_union, {3, 0, 0}));
  EXPECT_TRUE(inside(inv_inter, {-1.2, 0, 0}));   // outside b: outside the intersection
  EXPECT_FALSE(inside(inv_inter, {0, 0, 0}));
  EXPECT_FALSE(solid_extent(inv_union).finite());   // the outside of two spheres is unbounded
}

// ---- clipped_by and bounded_by -----------------------------------------------------------------------------------

TEST(Csg, ClippedByKeepsOnlyHitsInsideTheClip) {
  // sphere { 0, 1 clipped_by { plane { y, 0 } } }: an open lower hemisphere.
  const Primitive c = make_csg(CsgOperation::union_, {sphere({0, 0, 0}, 1)}, {plane({0, 1, 0}, 0)});
  const std::vector<double> down = sorted_depths(c, ray({0, 5, 0}, {0, -1, 0}));
  ASSERT_EQ(down.size(), 1u);
  EXPECT_DOUBLE_EQ(down[0], 6.0);   // only the bottom pole
  const std::vector<double> above = sorted_depths(c, ray({-5, 0.5, 0}, {1, 0, 0}));
  EXPECT_TRUE(above.empty());
  EXPECT_TRUE(inside(c, {0, -0.5, 0}));
  EXPECT_FALSE(inside(c, {0, 0.5, 0}));   // inside the sphere, outside the clip
}

TEST(Csg, BoundedByCullsRaysThatMissTheBound) {
  // A sphere bounded by a box that covers only its left half: rays missing the box see nothing, even where they
  // would hit the sphere; a ray starting inside the bound sees the whole sphere.
  const Primitive s = sphere({0, 0, 0}, 1);
  const Primitive bounded = make_csg(CsgOperation::union_, {s}, {}, {box({-2, -2, -2}, {0, 2, 2})});
  EXPECT_EQ(sorted_depths(bounded, ray({-0.5, 0, -5}, {0, 0, 1})).size(), 2u);
  EXPECT_TRUE(sorted_depths(bounded, ray({0.5, 0, -5}, {0, 0, 1})).empty());
  EXPECT_EQ(sorted_depths(bounded, ray({-1, 0, 0}, {1, 0, 0})).size(), 1u);   // starts inside: the far side
  EXPECT_TRUE(inside(bounded, {0.5, 0, 0}));   // bounds never change the inside test
}

TEST(Csg, BoundingObjectsGiveTheirBoxWhenItIsSmaller) {
  // POV-Ray's Parse_Object_Mods: the bounding objects' box replaces the object's own when its volume is smaller,
  // and rays missing it miss the object (also after the bound itself was removed at placement).
  const Primitive s = sphere({0, 0, 0}, 1);
  const Primitive half = with_bounding_box_from(make_csg(CsgOperation::union_, {s}), {box({0, -1, -1}, {2, 1, 1})});
  EXPECT_TRUE(sorted_depths(half, ray({-0.5, 0, -5}, {0, 0, 1})).empty());
  EXPECT_EQ(sorted_depths(half, ray({0.5, 0, -5}, {0, 0, 1})).size(), 2u);
  // A ray meeting the box sees the whole object, also where its hits lie outside the box.
  const std::vector<double> t = sorted_depths(half, ray({-5, 0, 0.2}, {1, 0, 0}));
  ASSERT_EQ(t.size(), 2u);
  EXPECT_LT(-5 + t[0], 0.0);
  EXPECT_LE(world_bounds(half).hi.x, 2.0 + 1e-6);
  EXPECT_GE(world_bounds(half).lo.x, -1e-6);
  // A box larger than the object's own changes nothing; inverted bounding objects are left out.
  const Primitive big = with_bounding_box_from(make_csg(CsgOperation::union_, {s}), {box({-3, -3, -3}, {3, 3, 3})});
  EXPECT_EQ(sorted_depths(big, ray({-0.5, 0, -5}, {0, 0, 1})).size(), 2u);
  Primitive inverted_box = box({0, -1, -1}, {2, 1, 1});
  inverted_box.inverse = true;
  const Primitive skip = with_bounding_box_from(make_csg(CsgOperation::union_, {s}), {inverted_box});
  EXPECT_EQ(sorted_depths(skip, ray({-0.5, 0, -5}, {0, 0, 1})).size(), 2u);
}

// ---- Shadow crossings and the accelerator ------------------------------------------------------------------------

TEST(Csg, ShadowRaysSeeEverySurvivingCrossing) {
  const Primitive a = sphere({-0.5, 0, 0}, 1), b = sphere({0.5, 0, 0}, 1);
  auto crossings = [](const Primitive& p) {
    const Accelerator acc({p});
    int n = 0;
    acc.for_each_shadow_hit(ray({-10, 0, 0}, {1, 0, 0}), tolerance::shadow, 20.0, [&](std::uint32_t, const SurfaceHit&) {
      ++n;
      return true;
    });
    return n;
  };
  EXPECT_EQ(crossings(make_csg(CsgOperation::merge, {a, b})), 2);
  EXPECT_EQ(crossings(make_csg(CsgOperation::union_, {a, b})), 4);
}

TEST(Csg, AcceleratorMatchesBruteForceOverCsgNodes) {
  std::mt19937 rng(31337);
  std::uniform_real_distribution<double> spread(-20, 20);
  std::vector<Primitive> prims;
  for (int k = 0; k < 80; ++k) {
    const Primitive p = moved(random_tree(rng, 2), {spread(rng), spread(rng), spread(rng)}).build();
    if (p.type == ShapeType::csg) prims.push_back(p);
  }
  prims.push_back(plane({0, 1, 0}, -25));
  const Accelerator acc(prims);
  for (int k = 0; k < 2000; ++k) {
    const Vec3 o{spread(rng) * 2, spread(rng) * 2, spread(rng) * 2};
    const Ray r = ray(o, random_unit(rng));
    const Hit fast = acc.closest_hit(r, tolerance::min_isect_depth, tolerance::bound_huge);
    const Hit slow = acc.closest_hit_brute_force(r, tolerance::min_isect_depth, tolerance::bound_huge);
    ASSERT_EQ(fast.primitive, slow.primitive) << k;
    if (fast.found()) {
      EXPECT_EQ(fast.t, slow.t);
      EXPECT_EQ(fast.surface.leaf, slow.surface.leaf);
    }
  }
}

}  // namespace
