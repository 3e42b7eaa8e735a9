// Blob.
//
// SDL: `blob { threshold T  sphere { C, R, S }…  cylinder { B, A, R, S }…  [sturm] object_modifiers... }` (POV-Ray
// 3.7 reference "Blob"): the solid where the summed density of the components exceeds the threshold; a component of
// strength S and radius R adds S·(1 − r²/R²)² within distance R. Primitive: data = BlobData (blob_build.cpp).
//
// POV-Ray behaviour reproduced here (facts read from source/backend/shape/blob.cpp, 3.7-stable):
// - The ray goes to blob space with its direction normalised (length L). Each element's span along the ray is found
//   from its sphere (the ellipsoid, cylinder and hemispheres in their own space, direction normalised there too);
//   span ends below 1e-2 (DEPTH_TOLERANCE, in the element's own units) become 0, and an element whose span is
//   then empty is skipped. The spans' ends are sorted into intervals (a new end goes before equal ones).
// - Depths are measured from the first interval's start (or from the origin when that is below 1e-3) and scaled by
//   the farthest interval end, so the quartics live in [0, 1]. Walking the intervals, each entering element adds
//   its quartic in the depth (density along the ray) and each exiting one takes it off; an interval with nothing
//   active, or shorter than 1e-10, is skipped, as is one whose quartic (on the interval, as a Bézier curve) has
//   control points all of one sign. Otherwise the quartic minus the threshold is solved (POV-Ray's
//   Solve_Polynomial with 1e-11 order reduction, Sturm sequences with `sturm`) and its roots inside the interval
//   are hits when their world depth lies in (1e-2, MAX_DISTANCE). The walk ends after the first interval with a
//   hit (POV-Ray's rule for a blob that is no CSG child).
// - Inside: summed density > threshold − 1e-6; `inverse` negates the test.
// - Normal: the sum over elements of (−2c0·r² − c1)·(point − centre) (the cylinder's radial part only; ellipsoids
//   and hemispheres carried out of their own space by the inverse transpose), normalised ((1, 0, 0) when zero),
//   then carried to world and normalised.
// - Bounds: the union of the bounding spheres' boxes of the positive elements.
#include <algorithm>
#include <cmath>

#include "renderer/shapes/blob.hpp"
#include "renderer/shapes/many_roots.hpp"
#include "runtime/polynomial_roots.hpp"

namespace povtrace::render::shapes {

namespace {
constexpr double depth_tolerance = 1e-2;    // blob.cpp DEPTH_TOLERANCE
constexpr double inside_tolerance = 1e-6;   // blob.cpp INSIDE_TOLERANCE
constexpr double small_tolerance = 1e-3;    // SMALL_TOLERANCE
using Kind = BlobElement::Kind;

const BlobData& data_of(const Primitive& p) { return static_cast<const BlobData&>(*p.data); }

struct Span {
  double t0 = tolerance::bound_huge, t1 = -tolerance::bound_huge;
};

void extend(Span& s, double t) {
  s.t0 = std::min(s.t0, t);
  s.t1 = std::max(s.t1, t);
}

// The chord of the sphere |P − centre|² = radius2 along the unit direction; false when the ray misses (d < 1e-10).
bool chord(Vec3 p, Vec3 d, Vec3 centre, double radius2, double& near, double& far) {
  const Vec3 v = p - centre;
  const double b = dot(v, d);
  double disc = b * b - dot(v, v) + radius2;
  if (disc < tolerance::epsilon) return false;
  disc = std::sqrt(disc);
  near = -b - disc;
  far = -b + disc;
  return true;
}

// Span ends below mindist become 0; the span is empty when its ends then coincide.
bool clamp_span(Span& s, double mindist) {
  if (s.t0 < mindist) s.t0 = 0.0;
  if (s.t1 < mindist) s.t1 = 0.0;
  return s.t1 != s.t0;
}

bool cylinder_span(const BlobElement& e, Vec3 p, Vec3 d, double len, Span& s) {
  const double a = d.x * d.x + d.y * d.y;
  if (a > tolerance::epsilon) {
    const double b = p.x * d.x + p.y * d.y, c = p.x * p.x + p.y * p.y - e.radius2;
    double disc = b * b - a * c;
    if (disc > tolerance::epsilon) {
      disc = std::sqrt(disc);
      for (const double t : {(-b + disc) / a, (-b - disc) / a}) {
        const double w = p.z + t * d.z;
        if (w >= 0.0 && w <= e.length) extend(s, t);
      }
    }
  }
  if (std::abs(d.z) > tolerance::epsilon) {
    for (const double h : {0.0, e.length}) {
      const double t = (h - p.z) / d.z, u = p.x + t * d.x, v = p.y + t * d.y;
      if (u * u + v * v <= e.radius2) extend(s, t);
    }
  }
  s.t0 /= len;
  s.t1 /= len;
  return s.t0 < s.t1;
}

// The hemisphere z <= 0 (base) or z >= 0 (apex, after moving the origin to the apex): the sphere's chord cut at
// the plane.
bool hemisphere_span(bool apex, double radius2, Vec3 p, Vec3 d, double len, double mindist, Span& s) {
  double near = 0, far = 0;
  if (!chord(p, d, Vec3{}, radius2, near, far)) return false;
  const double z1 = p.z + near * d.z, z2 = p.z + far * d.z;
  const auto in_half = [&](double z) { return apex ? z > 0.0 : z < 0.0; };
  if (!in_half(z1) && !in_half(z2)) return false;
  if (!(in_half(z1) && in_half(z2))) {
    const double t = -p.z / d.z;
    if (!in_half(z1)) near = t < mindist ? 0.0 : t;
    else far = t < mindist ? 0.0 : t;
  }
  s.t0 = near / len;
  s.t1 = far / len;
  return true;
}

bool element_span(const BlobElement& e, Vec3 p, Vec3 d, double mindist, Span& s) {
  if (e.kind == Kind::sphere) {
    if (!chord(p, d, e.centre, e.radius2, s.t0, s.t1)) return false;
    return clamp_span(s, mindist);
  }
  Vec3 pp = e.element_from_blob.point(p), dd = e.element_from_blob.vector(d);
  const double len = length(dd);
  dd = dd * (1.0 / len);
  switch (e.kind) {
    case Kind::ellipsoid:
      if (!chord(pp, dd, e.centre, e.radius2, s.t0, s.t1)) return false;
      s.t0 /= len;
      s.t1 /= len;
      return clamp_span(s, mindist);
    case Kind::cylinder:
      if (!cylinder_span(e, pp, dd, len, s)) return false;
      return clamp_span(s, mindist) && s.t0 < s.t1;
    case Kind::apex_hemisphere: pp.z -= e.length; [[fallthrough]];
    default: return hemisphere_span(e.kind == Kind::apex_hemisphere, e.radius2, pp, dd, len, mindist, s);
  }
}

struct Interval {
  double bound = 0;
  int element = 0;
  bool entering = true;
};

// POV-Ray's insert_hit: each end goes before the first existing end that is not smaller.
void insert_span(std::vector<Interval>& list, int element, const Span& s) {
  auto at = std::find_if(list.begin(), list.end(), [&](const Interval& i) { return !(s.t0 > i.bound); });
  at = list.insert(at, Interval{s.t0, element, true});
  at = std::find_if(at + 1, list.end(), [&](const Interval& i) { return !(s.t1 > i.bound); });
  list.insert(at, Interval{s.t1, element, false});
}

// The density of element e along P + t·D as a quartic in t (highest power first), D scaled by `scale`.
void element_quartic(const BlobElement& e, Vec3 p, Vec3 d, double scale, double* f) {
  double t0 = 0, t1 = 0, t2 = 0;
  if (e.kind == Kind::sphere) {
    const Vec3 v = p - e.centre;
    t0 = dot(v, v), t1 = dot(v, d), t2 = scale * scale;
  } else {
    Vec3 pp = e.element_from_blob.point(p);
    const Vec3 dd = e.element_from_blob.vector(d);
    if (e.kind == Kind::ellipsoid) pp = pp - e.centre;
    if (e.kind == Kind::apex_hemisphere) pp.z -= e.length;
    if (e.kind == Kind::cylinder) {
      t0 = pp.x * pp.x + pp.y * pp.y, t1 = pp.x * dd.x + pp.y * dd.y, t2 = dd.x * dd.x + dd.y * dd.y;
    } else {
      t0 = dot(pp, pp), t1 = dot(pp, dd), t2 = dot(dd, dd);
    }
  }
  const double c0 = e.c[0], c1 = e.c[1], c2 = e.c[2];
  f[0] = c0 * t2 * t2;
  f[1] = 4.0 * c0 * t1 * t2;
  f[2] = 2.0 * c0 * (2.0 * t1 * t1 + t0 * t2) + c1 * t2;
  f[3] = 2.0 * t1 * (2.0 * c0 * t0 + c1);
  f[4] = t0 * (c0 * t0 + c1) + c2;
}

// Whether the quartic c on [l, l + w] keeps one sign: its Bézier control points all >= 0 or all <= 0.
bool one_signed(const double* c, double l, double w) {
  const double n0 = c[0] * w * w * w * w, n1 = (c[1] + 4.0 * c[0] * l) * w * w * w;
  const double n2 = (3.0 * l * (2.0 * c[0] * l + c[1]) + c[2]) * w * w;
  const double n3 = (2.0 * l * (2.0 * l * (c[0] * l + 0.75 * c[1]) + c[2]) + c[3]) * w;
  const double n4 = l * (l * (l * (c[0] * l + c[1]) + c[2]) + c[3]) + c[4];
  const double dk[5] = {n4, n4 + 0.25 * n3, n4 + 0.5 * (n3 + n2 / 3.0), n4 + 0.5 * (1.5 * n3 + n2 + 0.5 * n1),
                        n4 + n3 + n2 + n1 + n0};
  bool all_pos = true, all_neg = true;
  for (const double v : dk) {
    all_pos = all_pos && v >= 0.0;
    all_neg = all_neg && v <= 0.0;
  }
  return all_pos || all_neg;
}
}  // namespace

void BlobShape::roots(const Primitive& p, const Ray& ray, RootList& out) {
  const BlobData& b = data_of(p);
  Vec3 o = p.transformed ? p.object_from_world.point(ray.origin) : ray.origin;
  Vec3 d = p.transformed ? p.object_from_world.vector(ray.direction) : ray.direction;
  const double len = p.transformed ? length(d) : 1.0;
  d = d * (1.0 / len);
  thread_local std::vector<Interval> intervals;
  intervals.clear();
  for (std::size_t i = 0; i < b.elements.size(); ++i)
    if (Span s; element_span(b.elements[i], o, d, depth_tolerance, s)) insert_span(intervals, int(i), s);
  if (intervals.empty()) return;
  double start = intervals[0].bound;
  if (start < small_tolerance) start = 0.0;
  double max_bound = -tolerance::bound_huge;
  for (auto& i : intervals) {
    i.bound -= start;
    max_bound = std::max(max_bound, i.bound);
  }
  o = o + d * start;
  if (max_bound != 0.0) {
    d = d * max_bound;
    for (auto& i : intervals) i.bound /= max_bound;
  } else {
    max_bound = 1.0;
  }
  thread_local std::vector<double> element_coeffs;
  element_coeffs.assign(b.elements.size() * 5, 0.0);
  double coeffs[5] = {0, 0, 0, 0, -b.threshold};
  int active = 0;
  const std::size_t before = out.size();
  for (std::size_t i = 0; i < intervals.size(); ++i) {
    double* f = &element_coeffs[static_cast<std::size_t>(intervals[i].element) * 5];
    if (intervals[i].entering) {
      ++active;
      element_quartic(b.elements[static_cast<std::size_t>(intervals[i].element)], o, d, max_bound, f);
      for (int j = 0; j < 5; ++j) coeffs[j] += f[j];
    } else {
      for (int j = 0; j < 5; ++j) coeffs[j] -= f[j];
      if (--active == 0) continue;
    }
    if (i + 1 < intervals.size() && std::abs(intervals[i].bound - intervals[i + 1].bound) < tolerance::epsilon) continue;
    if (i + 1 >= intervals.size()) break;   // past the last end nothing is active
    const double lo = intervals[i].bound, hi = intervals[i + 1].bound;
    if (one_signed(coeffs, lo, hi - lo)) continue;
    double roots[poly::max_degree];
    const int n = poly::solve_polynomial(4, coeffs, roots, b.sturm, 1e-11, tolerance::max_distance);
    for (int k = 0; k < n; ++k) {
      if (!(roots[k] >= lo && roots[k] <= hi)) continue;
      const double depth = (roots[k] * max_bound + start) / len;
      if (depth > depth_tolerance && depth < tolerance::max_distance) out.push_back(Root{depth, 0});
    }
    if (out.size() != before) return;
  }
}

namespace {
double element_density(const BlobElement& e, Vec3 q) {
  Vec3 pp = e.transformed ? e.element_from_blob.point(q) : q;
  double r2 = 0;
  switch (e.kind) {
    case Kind::sphere:
    case Kind::ellipsoid: {
      const Vec3 v = pp - e.centre;
      r2 = dot(v, v);
      if (!(r2 < e.radius2)) return 0.0;
      break;
    }
    case Kind::base_hemisphere:
    case Kind::apex_hemisphere:
      if (e.kind == Kind::apex_hemisphere) pp.z -= e.length;
      if (e.kind == Kind::apex_hemisphere ? !(pp.z >= 0.0) : !(pp.z <= 0.0)) return 0.0;
      r2 = dot(pp, pp);
      if (!(r2 <= e.radius2)) return 0.0;
      break;
    case Kind::cylinder:
      if (!(pp.z >= 0.0 && pp.z <= e.length)) return 0.0;
      r2 = pp.x * pp.x + pp.y * pp.y;
      if (!(r2 <= e.radius2)) return 0.0;
      break;
  }
  return r2 * (r2 * e.c[0] + e.c[1]) + e.c[2];
}

// The element's share of the normal at blob-space point q (its density's gradient, up to a factor −2).
Vec3 element_normal(const BlobElement& e, Vec3 q) {
  Vec3 pp = e.transformed ? e.element_from_blob.point(q) : q;
  if (e.kind == Kind::sphere || e.kind == Kind::ellipsoid) pp = pp - e.centre;
  if (e.kind == Kind::apex_hemisphere) pp.z -= e.length;
  double r2 = dot(pp, pp);
  if (e.kind == Kind::base_hemisphere && !(pp.z <= 0.0)) return {};
  if (e.kind == Kind::apex_hemisphere && !(pp.z >= 0.0)) return {};
  if (e.kind == Kind::cylinder) {
    if (!(pp.z >= 0.0 && pp.z <= e.length)) return {};
    r2 = pp.x * pp.x + pp.y * pp.y;
    pp.z = 0.0;
  }
  if (!(r2 <= e.radius2)) return {};
  const double weight = -2.0 * e.c[0] * r2 - e.c[1];
  const Vec3 v = e.transformed ? e.element_from_blob.normal_from_inverse(pp) : pp;
  return v * weight;
}
}  // namespace

void blob_materials(const Primitive& p, Vec3 world_point, MaterialBlend& blend) {
  const BlobData& b = data_of(p);
  const Vec3 q = p.transformed ? p.object_from_world.point(world_point) : world_point;
  blend.count = 0;
  float sum = 0.0f;
  for (const auto& e : b.elements) {
    const auto density = static_cast<float>(std::fabs(element_density(e, q)));
    if (density > 0.0f) {
      blend.add(p.element_materials + e.component, density);
      sum += density;
    }
  }
  if (blend.count == 0) {   // no field reaches the point (a hit found at the threshold's edge): POV-Ray shades nothing
    return;
  }
  const auto scale = static_cast<float>(1.0 / sum);
  for (int k = 0; k < blend.count; ++k) blend.set_weight(k, static_cast<float>(blend.weight_of(k)) * scale);
}

std::uint32_t blob_texture_count(const Primitive& p) { return data_of(p).textured_components; }

Vec3 BlobShape::normal(const Primitive& p, Vec3 world_point) {
  const BlobData& b = data_of(p);
  const Vec3 q = p.transformed ? p.object_from_world.point(world_point) : world_point;
  Vec3 n{};
  for (const auto& e : b.elements) n += element_normal(e, q);
  const double v = dot(n, n);
  n = v == 0.0 ? Vec3{1, 0, 0} : n * (1.0 / std::sqrt(v));
  if (!p.transformed) return n;
  const Vec3 w = p.object_from_world.normal_from_inverse(n);
  return w * (1.0 / length(w));
}

bool BlobShape::inside(const Primitive& p, Vec3 world_point) {
  const BlobData& b = data_of(p);
  const Vec3 q = p.transformed ? p.object_from_world.point(world_point) : world_point;
  double density = 0;
  for (const auto& e : b.elements) density += element_density(e, q);
  return (density > b.threshold - inside_tolerance) != p.inverse;
}

Bounds BlobShape::object_bounds(const Primitive& p) {
  Bounds out;
  for (const auto& e : data_of(p).elements) {
    if (!(e.c[2] > 0.0)) continue;
    Vec3 c = e.centre;
    double r2 = e.radius2;
    if (e.kind == Kind::base_hemisphere) c = Vec3{};
    if (e.kind == Kind::apex_hemisphere) c = Vec3{0, 0, e.length};
    if (e.kind == Kind::cylinder) c = Vec3{0, 0, 0.5 * e.length}, r2 += 0.25 * e.length * e.length;
    const double r = std::sqrt(r2);
    if (!e.transformed) {
      out.extend(Bounds{c - Vec3{r, r, r}, c + Vec3{r, r, r}});
      continue;
    }
    const Matrix blob_from_element = e.element_from_blob.inverse();
    for (int k = 0; k < 8; ++k)
      out.extend(blob_from_element.point(c + Vec3{k & 1 ? r : -r, k & 2 ? r : -r, k & 4 ? r : -r}));
  }
  return out;
}

}  // namespace povtrace::render::shapes
