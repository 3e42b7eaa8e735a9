// Superellipsoid.
//
// SDL: `superellipsoid { <e, n> object_modifiers... }` (POV-Ray 3.7 reference "Superquadric Ellipsoid"): the solid
// (|x|^(2/e) + |y|^(2/e))^(e/n) + |z|^(2/n) <= 1. Primitive: a = the powers (2/e, e/n, 2/n) as POV-Ray's parser
// stores them.
//
// POV-Ray behaviour reproduced here (facts read from source/backend/shape/super.cpp, 3.7-stable):
// - The implicit function is evaluated in the nested form g(g(|x|, |y|, 2/e), |z|, 2/n) − 1 with
//   g(a, b, p) = max·(1 + (min/max)^p)^(1/p) (0 when both are 0), integer powers 0…6 by multiplication.
// - The world ray goes to object space with its direction normalised (length L). It is clipped to the box
//   [−1.01, 1.01]³ (slab by slab, an axis-parallel ray outside a slab misses; the exit must be beyond 1e-4 and
//   the entry is raised to 1e-4). The depths where the ray crosses the nine planes x=±y, x=±z, y=±z, x=0, y=0,
//   z=0 within the clipped span (widened by 1e-10 of its length) cut it into pieces, sorted.
// - Walking the piece ends in order: an end where |f| < 1e-10 is a hit; a piece whose ends differ in sign has a
//   hit found by up to 20 rounds of secant-and-midpoint narrowing on the points (the hit depth is the distance of
//   the final point from the origin); a piece without a sign change is probed from its start by a secant walk
//   (first step 1e-4 of the piece, at most 20 steps, giving up when |f| grows or a step exceeds the piece) that
//   may find a crossing, which is then narrowed as above. A probed hit that is refused by the depth rules ends
//   the walk.
// - A hit is kept when its world depth (object depth / L) lies in (1e-4, MAX_DISTANCE).
// - Inside: f < 1e-10; `inverse` negates the test.
// - Normal: POV-Ray's own gradient expression (see SuperellipsoidShape::normal), carried to world by the inverse
//   transpose and normalised.
// - Bounds: the cube [−1.0001, 1.0001]³ carried to world.
#include <algorithm>
#include <cmath>
#include <utility>

#include "renderer/shapes/many_roots.hpp"
#include "renderer/shapes/box.hpp"
#include "renderer/shapes/superellipsoid.hpp"

namespace povtrace::render::shapes {

namespace {
constexpr double depth_tolerance = 1e-4;   // super.cpp DEPTH_TOLERANCE
constexpr double zero_tolerance = 1e-10;   // super.cpp ZERO_TOLERANCE
constexpr double box_half = 1.01;          // super.cpp MIN_VALUE/MAX_VALUE
constexpr int max_iterations = 20;

// x^e with the integer powers 0…6 multiplied out (as POV-Ray does: the results differ from pow in the last bit).
double power(double x, double e) {
  if (!(e >= 0.0 && e <= 6.0)) return std::pow(x, e);   // also NaN and ±inf (e = 0 written): no int cast of them
  const int i = static_cast<int>(e);
  if (e != static_cast<double>(i)) return std::pow(x, e);
  const double x2 = x * x;
  switch (i) {
    case 0: return 1.0;
    case 1: return x;
    case 2: return x2;
    case 3: return x2 * x;
    case 4: return x2 * x2;
    case 5: return x2 * x2 * x;
    default: return x2 * x2 * x2;
  }
}

// The two-argument superellipse norm, scaled by the larger argument so that the power stays in [1, 2].
double norm(double a, double b, double e) {
  const double big = a > b ? a : b, small = a > b ? b : a;
  if (!(a > b) && b == 0.0) return 0.0;
  double g = 1.0 + power(small / big, e);
  if (g != 1.0) g = power(g, 1.0 / e);
  return g * big;
}

struct Powers {
  Vec3 e;
  double operator()(Vec3 p) const {
    return norm(norm(std::abs(p.x), std::abs(p.y), e.x), std::abs(p.z), e.z) - 1.0;
  }
};

// Clips the ray to the box [−1.01, 1.01]³ as POV-Ray's BoxShape::intersect does; false when it misses.
bool clip_slab(double o, double d, double& t_min, double& t_max, bool first) {
  if (std::abs(d) > tolerance::epsilon) {
    double lo = (-box_half - o) / d, hi = (box_half - o) / d;
    if (d < 0.0) std::swap(lo, hi);
    if (first) {
      t_min = lo;
      t_max = hi;
      return !(hi < tolerance::epsilon) && !(lo > hi);
    }
    if (hi < t_max) {
      if (hi < tolerance::epsilon) return false;
      if (lo > t_min) {
        if (lo > hi) return false;
        t_min = lo;
      } else if (t_min > hi) {
        return false;
      }
      t_max = hi;
    } else if (lo > t_min) {
      if (lo > t_max) return false;
      t_min = lo;
    }
    return true;
  }
  if (o < -box_half || o > box_half) return false;
  if (first) {
    t_min = -tolerance::bound_huge;
    t_max = tolerance::bound_huge;
  }
  return true;
}

bool clip_to_box(Vec3 o, Vec3 d, double& t_min, double& t_max) {
  return clip_slab(o.x, d.x, t_min, t_max, true) && clip_slab(o.y, d.y, t_min, t_max, false) &&
         clip_slab(o.z, d.z, t_min, t_max, false);
}

// The piece ends: the clipped span and the crossings of the planes that cut the shape into monotonic pieces.
int piece_ends(Vec3 o, Vec3 d, double t_min, double t_max, double* ends) {
  static constexpr Vec3 planes[9] = {{1, 1, 0}, {1, -1, 0}, {1, 0, 1}, {1, 0, -1}, {0, 1, 1},
                                     {0, 1, -1}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  int count = 0;
  ends[count++] = t_min;
  ends[count++] = t_max;
  const double widen = tolerance::epsilon * (t_max - t_min);
  const double lo = t_min - widen, hi = t_max + widen;
  for (const Vec3& n : planes) {
    const double along = dot(d, n);
    if (std::abs(along) < tolerance::epsilon) continue;
    const double t = -dot(o, n) / along;
    if (t >= lo && t <= hi) ends[count++] = t;
  }
  // At most 11 values: an insertion sort (std::sort's small-range path trips GCC's array-bounds analysis here).
  for (int i = 1; i < count; ++i)
    for (int k = i; k > 0 && ends[k - 1] > ends[k]; --k) std::swap(ends[k - 1], ends[k]);
  return count;
}

// Narrows a sign change between p0 (value v0) and p1 (value v1) to a surface point.
Vec3 narrow(const Powers& f, double v0, Vec3 p0, double v1, Vec3 p1) {
  for (int i = 0; i < max_iterations; ++i) {
    if (std::abs(v0) < zero_tolerance) return p0;
    if (std::abs(v1) < zero_tolerance) return p1;
    const Vec3 secant = p0 + (p1 - p0) * (std::abs(v0) / std::abs(v1 - v0));
    const Vec3 middle = p0 + (p1 - p0) * 0.5;
    const double vs = f(secant), vm = f(middle);
    if (vs * vm < 0.0) {
      v0 = vs, p0 = secant, v1 = vm, p1 = middle;
    } else {
      const bool use_secant = std::abs(vs) < std::abs(vm);
      const double v = use_secant ? vs : vm;
      const Vec3 q = use_secant ? secant : middle;
      if (v0 * v < 0.0) v1 = v, p1 = q;
      else v0 = v, p0 = q;
    }
  }
  return std::abs(v0) < std::abs(v1) ? p0 : p1;
}

// A piece without a sign change may still touch or cross the surface between samples: a secant walk from its start.
bool probe(const Powers& f, Vec3 o, Vec3 d, double t0, Vec3 p0, double v0, double t1, Vec3& found) {
  double dt0 = t0, dt1 = t0 + 0.0001 * (t1 - t0), step = 0.0;
  const double max_step = t1 - t0;
  for (int i = 0; dt0 < t1 && i < max_iterations; ++i) {
    const Vec3 p1 = o + d * dt1;
    const double v1 = f(p1);
    if (v0 * v1 < 0.0) {
      found = narrow(f, v0, p0, v1, p1);
      return true;
    }
    if (std::abs(v1) < zero_tolerance) {
      found = p1;
      return true;
    }
    if ((v0 > 0.0 && v1 > v0) || (v0 < 0.0 && v1 < v0) || v1 == v0) return false;
    step = v1 * (dt1 - dt0) / (v1 - v0);
    if (std::abs(step) > max_step) return false;
    v0 = v1;
    dt0 = dt1;
    dt1 -= step;
  }
  return false;
}

bool keep(double object_depth, double len, RootList& out) {
  const double depth = object_depth / len;
  if (!(depth > depth_tolerance && depth < tolerance::max_distance)) return false;
  out.push_back(Root{depth, 0});
  return true;
}
}  // namespace

void SuperellipsoidShape::roots(const Primitive& p, const Ray& ray, RootList& out) {
  const Powers f{p.a};
  const Vec3 o = p.transformed ? p.object_from_world.point(ray.origin) : ray.origin;
  Vec3 d = p.transformed ? p.object_from_world.vector(ray.direction) : ray.direction;
  const double len = length(d);
  d = d * (1.0 / len);
  double t_min = 0, t_max = 0;
  if (!clip_to_box(o, d, t_min, t_max) || t_max < depth_tolerance) return;
  t_min = std::max(t_min, depth_tolerance);
  double ends[11];
  const int count = piece_ends(o, d, t_min, t_max, ends);
  if (count <= 1) return;
  Vec3 p0 = o + d * ends[0];
  double v0 = f(p0);
  if (std::abs(v0) < zero_tolerance) keep(ends[0], len, out);
  for (int i = 1; i < count; ++i) {
    const Vec3 p1 = o + d * ends[i];
    const double v1 = f(p1);
    if (std::abs(v1) < zero_tolerance) {
      keep(ends[i], len, out);
    } else if (v0 * v1 < 0.0) {
      keep(length(narrow(f, v0, p0, v1, p1) - o), len, out);
    } else if (Vec3 q; probe(f, o, d, ends[i - 1], p0, v0, ends[i], q)) {
      if (!keep(length(q - o), len, out)) break;
    }
    v0 = v1;
    p0 = p1;
  }
}

Vec3 SuperellipsoidShape::normal(const Primitive& p, Vec3 world_point) {
  const Vec3 e = p.a;
  Vec3 q = p.transformed ? p.object_from_world.point(world_point) : world_point;
  // On the surface (|x|^ex + |y|^ex)^ey = 1 − |z|^ez: POV-Ray's expression for the gradient, scaled per piece.
  double z_term = 0.0, ratio = 0.0;
  if (q.z != 0.0) {
    z_term = power(std::abs(q.z), e.z);
    q.z = z_term / q.z;
  }
  if (std::abs(q.x) > std::abs(q.y)) {
    ratio = power(std::abs(q.y / q.x), e.x);
    q.x = (1.0 - z_term) / q.x;
    q.y = q.y != 0.0 ? (1.0 - z_term) * ratio / q.y : 0.0;
  } else if (q.y != 0.0) {
    ratio = power(std::abs(q.x / q.y), e.x);
    q.x = q.x != 0.0 ? (1.0 - z_term) * ratio / q.x : 0.0;
    q.y = (1.0 - z_term) / q.y;
  }
  if (q.z != 0.0) q.z *= 1.0 + ratio;
  Vec3 n = p.transformed ? p.object_from_world.normal_from_inverse(q) : q;
  return n * (1.0 / length(n));
}

bool SuperellipsoidShape::inside(const Primitive& p, Vec3 world_point) {
  const Vec3 q = p.transformed ? p.object_from_world.point(world_point) : world_point;
  return (Powers{p.a}(q) < tolerance::epsilon) != p.inverse;
}

Bounds SuperellipsoidShape::object_bounds(const Primitive&) {
  return Bounds{Vec3{-1.0001, -1.0001, -1.0001}, Vec3{1.0001, 1.0001, 1.0001}};
}

}  // namespace povtrace::render::shapes
