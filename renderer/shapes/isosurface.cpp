// Isosurface.
//
// SDL: `isosurface { function { F } [contained_by { box {…} | sphere {…} }] [threshold T] [accuracy A]
// [max_gradient G] [max_trace N | all_intersections] [open] object_modifiers… }` (POV-Ray 3.7 reference
// "Isosurface"): where F(x, y, z) = T inside the container; F < T is inside. Primitive: data = IsosurfaceData.
//
// POV-Ray behaviour reproduced here (facts read from source/backend/shape/isosurf.cpp, 3.7-stable), with
// f(t) = F(P + t·D) − T along the object-space ray (D as transformed, so t is the world depth):
// - The container span [t1, t2] (isosurface_container.cpp; a sphere's depths divided by the direction's length),
//   t1 raised to 0. Closed: if t1 > A and f(t1) < 0 the container is hit at t1 and the search starts inside (the
//   sign of f flipped); if t1 ≤ A (the ray starts in the container) and f(t1) < 4·G·A, t1 becomes 5·A and the sign
//   flips when f(t1) < 0 there; then the container is hit at t2 when f(t2) < 0. A span shorter than A has no hits.
//   Otherwise, with t1 < A and the sign not flipped, |f(t1)| < 4·G·A moves t1 to 5·A the same way.
// - Up to max_trace roots: the span is halved recursively while f(a) + f(b) < G·|D|·(b − a) (the gradient bound
//   allows a root), down to pieces shorter than A; the first piece whose far end has f < 0 gives the root at that
//   end. Open isosurfaces flip the sign whenever f < 0 where a search starts. After a root the search goes on from
//   5·A beyond it with the sign flipped.
// - evaluate P0, P1, P2: the bound G above is the ray's own, starting from the one learnt before rendering
//   (learn_evaluate_gradient, at the end of this file). Each root search first lowers it to G·P2 when it is above
//   P0; each piece of the halving whose slope |f(b) − f(a)| / (|D|·(b − a)) = g has G < g·P1 raises it to g·P1² (and
//   that piece's allowance with it) for the rest of the ray.
// - Not reproduced: POV-Ray's per-thread cache that skips a search when the previous ray of the same thread came
//   close without a root, and, with `evaluate`, POV-Ray's carrying each ray's final G over to the next ray it
//   traces (the object's max_gradient only grows during a render). Both depend on the order POV-Ray's threads take
//   pixels in, so its own renders differ run to run; povtrace's rays start from a bound learnt once, the same for
//   any thread count.
// - Normal: the container face hit, or the sphere's radius where the point lies within 1e-10 of it, else the
//   forward differences of F over steps of A ((1, 0, 0) when all vanish).
// - Inside: within the container (boundary included) and F ≤ T.
#include <algorithm>
#include <cmath>

#include "runtime/function_value.hpp"   // the renderer evaluates the parser's compiled function
#include "renderer/shapes/isosurface.hpp"
#include "renderer/shapes/local_ray.hpp"
#include "renderer/shapes/many_roots.hpp"

namespace povtrace::render::shapes {

namespace {
const IsosurfaceData& data_of(const Primitive& p) { return static_cast<const IsosurfaceData&>(*p.data); }

double function_at(const IsosurfaceData& d, Vec3 q) {
  const double args[3] = {q.x, q.y, q.z};
  return sdl::evaluate_function(*d.function, args, nullptr, d.noise_generator);
}

// One ray's search: the object-space ray, the sign the function is taken with (POV-Ray's Inv3), and the gradient
// bound, which `evaluate` adapts as the search goes.
struct Search {
  const IsosurfaceData& d;
  Vec3 p, v;
  double sign = 1;
  double found = 0;
  double max_gradient;   // POV-Ray's maxg: the ray's gradient bound

  double raw(double t) const { return function_at(d, p + v * t) - d.threshold; }
  double signed_at(double t) const { return sign * raw(t); }

  struct End {
    double t, f;
  };
  // `inverse_span` is 1 / (|v|·span): the slope of the piece per unit of object space.
  bool halve(End a, End b, double dt, double span, double inverse_span) {
    if (d.evaluate) {
      const double slope = std::fabs((b.f - a.f) * inverse_span);
      const double p1 = d.evaluate_params[1];
      if (max_gradient < slope * p1) {
        max_gradient = slope * p1 * p1;
        dt = max_gradient * length(v) * span;
      }
    }
    if (span < d.accuracy) {
      if (!(b.f < 0)) return false;
      found = b.t;
      return true;
    }
    if (!(a.f + b.f - dt < 0)) return false;
    span *= 0.5;
    dt *= 0.5;
    const End mid{a.t + span, signed_at(a.t + span)};
    return halve(a, mid, dt, span, inverse_span * 2.0) || halve(mid, b, dt, span, inverse_span * 2.0);
  }

  bool find_root(double t1, double t2) {
    End a{t1, signed_at(t1)};
    if (!d.closed && a.f < 0.0) {
      sign = -sign;
      a.f = -a.f;
    }
    const End b{t2, signed_at(t2)};
    const double span = t2 - t1;
    if (d.evaluate && max_gradient > d.evaluate_params[0]) max_gradient *= d.evaluate_params[2];
    const double v_length = length(v);
    return halve(a, b, max_gradient * v_length * span, span, 1.0 / (v_length * span));
  }
};

std::optional<ContainerSpan> container_span(const Primitive& prim, const IsosurfaceData& d, const Ray& ray) {
  if (d.sphere_container) {
    const LocalRay r = local_ray(prim, ray);
    std::optional<ContainerSpan> s = sphere_container_span(r.p, r.d, d.centre, d.radius);
    if (!s) return std::nullopt;
    s->t1 /= r.len;
    s->t2 /= r.len;
    return s;
  }
  const Vec3 p = prim.transformed ? prim.object_from_world.point(ray.origin) : ray.origin;
  const Vec3 v = prim.transformed ? prim.object_from_world.vector(ray.direction) : ray.direction;
  return box_container_span(p, v, d.corner1, d.corner2);
}

// The closed container's own hits (see the top of this file); returns how many roots they use up.
int container_hits(Search& s, ContainerSpan& span, RootList& out) {
  const IsosurfaceData& d = s.d;
  const double near = 4.0 * s.max_gradient * d.accuracy;
  if (span.t1 > d.accuracy) {
    if (!(s.raw(span.t1) < 0.0)) return 0;
    out.push_back(Root{span.t1, static_cast<std::uint32_t>(span.side1), 0.0});
    s.sign = -s.sign;
    return 1;
  }
  if (s.raw(span.t1) < near) {
    span.t1 = 5.0 * d.accuracy;
    if (s.raw(span.t1) < 0) s.sign = -1;
  }
  if (s.raw(span.t2) < 0.0) out.push_back(Root{span.t2, static_cast<std::uint32_t>(span.side2), 0.0});
  return 0;
}

// The search along the object-space ray p + t·v through the container span: appends its roots to `out` and returns
// the gradient bound it ended with (which only `evaluate` changes from `start`).
double search_ray(const IsosurfaceData& d, Vec3 p, Vec3 v, ContainerSpan span, double start, RootList& out) {
  if (span.t1 < 0.0) span.t1 = 0.0;
  Search s{d, p, v, 1, 0, start};
  const std::size_t first = out.size();
  int traced = d.closed ? container_hits(s, span, out) : 0;
  double t2 = std::min(span.t2, tolerance::bound_huge);
  double t1 = std::min(t2, span.t1);
  if (t2 - t1 < d.accuracy) {
    out.resize(first);   // POV-Ray reports no intersection at all then
    return s.max_gradient;
  }
  if (t1 < d.accuracy && s.sign == 1 && std::fabs(s.raw(t1)) < 4.0 * s.max_gradient * d.accuracy) {
    t1 = 5.0 * d.accuracy;
    if (s.raw(t1) < 0) s.sign = -1;
  }
  for (; traced < d.max_trace; ++traced) {
    if (!s.find_root(t1, t2)) break;
    out.push_back(Root{s.found, 0, 0.0});
    t1 = s.found + 5.0 * d.accuracy;
    if (t2 - t1 < d.accuracy) break;
    s.sign = -s.sign;
  }
  return s.max_gradient;
}
}  // namespace

void IsosurfaceShape::roots(const Primitive& p, const Ray& ray, RootList& out) {
  const IsosurfaceData& d = data_of(p);
  const std::optional<ContainerSpan> found = container_span(p, d, ray);
  if (!found) return;
  search_ray(d, p.transformed ? p.object_from_world.point(ray.origin) : ray.origin,
             p.transformed ? p.object_from_world.vector(ray.direction) : ray.direction, *found, d.max_gradient, out);
}

Vec3 IsosurfaceShape::normal_at(const Primitive& p, std::uint32_t side, Vec3 world_point) {
  const IsosurfaceData& d = data_of(p);
  Vec3 n{};
  if (side >= 1 && side <= 6) {
    n[static_cast<int>(side - 1) / 2] = side % 2 ? -1.0 : 1.0;
  } else {
    const Vec3 q = p.transformed ? p.object_from_world.point(world_point) : world_point;
    const Vec3 radial = q - d.centre;
    if (d.sphere_container && std::fabs(length(radial) - d.radius) < tolerance::epsilon) {
      n = radial * (1.0 / d.radius);
    } else {
      const double f0 = function_at(d, q);
      for (int axis = 0; axis < 3; ++axis) {
        Vec3 step = q;
        step[axis] += d.accuracy;
        n[axis] = function_at(d, step) - f0;
      }
      if (n.x == 0 && n.y == 0 && n.z == 0) n.x = 1.0;
      n = n * (1.0 / length(n));
    }
  }
  if (!p.transformed) return n;
  n = p.object_from_world.normal_from_inverse(n);
  return n * (1.0 / length(n));
}


bool IsosurfaceShape::inside(const Primitive& p, Vec3 world_point) {
  const IsosurfaceData& d = data_of(p);
  const Vec3 q = p.transformed ? p.object_from_world.point(world_point) : world_point;
  bool in = true;
  if (d.sphere_container) {
    const Vec3 to_centre = d.centre - q;
    in = !(dot(to_centre, to_centre) > d.radius * d.radius);
  } else {
    for (int axis = 0; axis < 3; ++axis)
      in = in && !(q[axis] < d.corner1[axis] || q[axis] > d.corner2[axis]);
  }
  in = in && !(function_at(d, q) - d.threshold > 0);
  return in != p.inverse;
}

Bounds IsosurfaceShape::object_bounds(const Primitive& p) {
  const IsosurfaceData& d = data_of(p);
  if (!d.sphere_container) return Bounds{d.corner1, d.corner2};
  const Vec3 r{d.radius, d.radius, d.radius};
  return Bounds{d.centre - r, d.centre + r};
}

}  // namespace povtrace::render::shapes

namespace povtrace::render {

// POV-Ray carries each ray's final bound over to the object (max_gradient = max(max_gradient, maxg)), so its rays
// start from what the render has learnt so far, in whatever order its threads take pixels. povtrace learns it once,
// before rendering, from a fixed sequence of probe rays treated the same way (each starts from the bound learnt so
// far and leaves the larger of the two): parallel rays along ±x, ±y and ±z, straight and tilted, on a 10 × 10 grid
// over the container's faces. The same bound for any thread count; POV-Ray's own runs differ from each other.
void learn_evaluate_gradient(IsosurfaceData& d) {
  if (!d.evaluate) return;
  const Vec3 lo = d.sphere_container ? d.centre - Vec3{d.radius, d.radius, d.radius} : d.corner1;
  const Vec3 hi = d.sphere_container ? d.centre + Vec3{d.radius, d.radius, d.radius} : d.corner2;
  constexpr int grid = 10;
  constexpr double tilts[2][2] = {{0.0, 0.0}, {0.35, 0.2}};
  double learned = d.max_gradient;
  shapes::RootList roots;
  for (int axis = 0; axis < 3; ++axis) {
    const int b = (axis + 1) % 3, c = (axis + 2) % 3;
    for (const auto& tilt : tilts)
      for (double sign : {1.0, -1.0}) {
        Vec3 dir{};
        dir[axis] = sign;
        dir[b] = tilt[0];
        dir[c] = tilt[1];
        dir = dir * (1.0 / length(dir));
        const double margin = 0.01 * (hi[axis] - lo[axis]) + 1e-6;
        for (int i = 0; i < grid; ++i)
          for (int j = 0; j < grid; ++j) {
            Vec3 origin{};
            origin[axis] = sign > 0 ? lo[axis] - margin : hi[axis] + margin;
            origin[b] = lo[b] + (i + 0.5) / grid * (hi[b] - lo[b]);
            origin[c] = lo[c] + (j + 0.5) / grid * (hi[c] - lo[c]);
            const std::optional<ContainerSpan> span =
                d.sphere_container ? sphere_container_span(origin, dir, d.centre, d.radius)
                                   : box_container_span(origin, dir, d.corner1, d.corner2);
            if (!span) continue;
            roots.clear();
            learned = std::max(learned, shapes::search_ray(d, origin, dir, *span, learned, roots));
          }
      }
  }
  d.max_gradient = learned;
}

}  // namespace povtrace::render
