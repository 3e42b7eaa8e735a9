// ovus as POV-Ray 3.7 intersects it (source/backend/shape/ovus.cpp, 3.7-stable): in object space the ray (unit
// direction) meets the bottom sphere (centre 0, radius B), the top sphere (centre <0, B, 0>, radius T) and the
// spindle of the torus joining them, a quartic solved with a root tolerance of 1e-4. A sphere's crossings count
// only beyond its junction height (below bottom_vertical, above top_vertical), and POV-Ray stops looking once two
// of them are found; the spindle's count between the two heights where the point lies on the spindle (to 1e-4).
// Depths must exceed POV-Ray's EPSILON (1e-10).
#include "renderer/shapes/ovus.hpp"

#include <algorithm>
#include <cmath>
#include <memory>

#include "scene/ovus_geometry.hpp"
#include "runtime/polynomial_roots.hpp"

namespace povtrace::render::shapes {

namespace {
constexpr double kEpsilon = 1e-10;          // POV-Ray's EPSILON
constexpr double kRootTolerance = 1e-4;     // ovus.cpp ROOT_TOLERANCE

struct Dimensions {
  double bottom, top, connecting, vertical, horizontal, bottom_vertical, top_vertical;
};
Dimensions dims(const Primitive& p) {
  return {p.a.x, p.a.y, p.a.z, p.b.x, p.b.y, p.b.z, p.radius};
}

// The chord of a sphere along the unit direction d from o (POV-Ray's test: o inside, or the centre ahead by more
// than EPSILON, and a half chord² above EPSILON).
bool sphere_chord(Vec3 o, Vec3 d, Vec3 centre, double radius2, double& near, double& far) {
  const Vec3 to_centre = centre - o;
  const double oc2 = dot(to_centre, to_centre), closest = dot(to_centre, d);
  if (!(oc2 < radius2 || closest > kEpsilon)) return false;
  const double half2 = radius2 - oc2 + closest * closest;
  if (!(half2 > kEpsilon)) return false;
  const double half = std::sqrt(half2);
  near = closest - half;
  far = closest + half;
  return true;
}
}  // namespace

namespace {
struct OvusData : ShapeData {
  bool sturm = false;
};
}  // namespace

Primitive make_ovus(const Ovus& o, const Matrix& world_from_object) {
  Primitive p = placed_primitive(ShapeType::ovus, world_from_object);
  auto data = std::make_shared<OvusData>();
  data->sturm = o.sturm;
  p.data = std::move(data);
  const OvusGeometry g = ovus_geometry(o);
  p.a = Vec3{o.bottom_radius, o.top_radius, g.connecting_radius};
  p.b = Vec3{g.vertical_position, g.horizontal_position, g.bottom_vertical};
  p.radius = g.top_vertical;
  return p;
}

void OvusShape::roots(const Primitive& p, const Ray& ray, RootList& out) {
  const Dimensions s = dims(p);
  const Vec3 o = p.transformed ? p.object_from_world.point(ray.origin) : ray.origin;
  Vec3 d = p.transformed ? p.object_from_world.vector(ray.direction) : ray.direction;
  const double len = length(d);
  d = d * (1.0 / len);
  const auto keep = [&](double depth) {
    if (depth > kEpsilon) out.push_back(Root{depth / len, 0, 0});
  };
  int counted = 0;
  double near = 0, far = 0;
  if (sphere_chord(o, d, Vec3{0, 0, 0}, s.bottom * s.bottom, near, far)) {
    for (const double t : {near, far})
      if ((o + d * t).y < s.bottom_vertical) {
        ++counted;
        keep(t);
      }
  }
  if (counted > 1) return;
  if (sphere_chord(o, d, Vec3{0, s.bottom, 0}, s.top * s.top, near, far)) {
    for (const double t : {near, far})
      if ((o + d * t).y > s.top_vertical) {
        ++counted;
        keep(t);
      }
  }
  if (counted > 1) return;
  // The spindle: (x² + y'² + z² − R² − r²)² = 4R²(r² − y'²) along the ray, y' = y − vertical.
  const Vec3 q{o.x, o.y - s.vertical, o.z};
  const double big2 = s.horizontal * s.horizontal, small2 = s.connecting * s.connecting;
  const double py2 = q.y * q.y, dy2 = d.y * d.y, pdy = q.y * d.y;
  const double k1 = q.x * q.x + q.z * q.z + py2 - big2 - small2;
  const double k2 = q.x * d.x + q.z * d.z + pdy;
  const double c[5] = {1.0, 4.0 * k2, 2.0 * (k1 + 2.0 * (k2 * k2 + big2 * dy2)), 4.0 * (k2 * k1 + 2.0 * big2 * pdy),
                       k1 * k1 + 4.0 * big2 * (py2 - small2)};
  double r[4];
  const bool sturm = static_cast<const OvusData&>(*p.data).sturm;
  int n = poly::solve_polynomial(4, c, r, sturm, kRootTolerance, tolerance::max_distance);
  // POV-Ray keeps two spindle depths: the first valid root (walking its list from the end) and the last one after it.
  double first = -100, second = -100;
  while (n--) {
    const Vec3 at = o + d * r[n];
    if (!(at.y > s.bottom_vertical && at.y < s.top_vertical)) continue;
    const double horizontal = std::sqrt(at.x * at.x + at.z * at.z);
    const double off = (horizontal + s.horizontal) * (horizontal + s.horizontal) +
                       (at.y - s.vertical) * (at.y - s.vertical);
    if (std::fabs(off - small2) < kRootTolerance) (first < 0 ? first : second) = r[n];
  }
  keep(first);
  keep(second);
}

Vec3 OvusShape::normal(const Primitive& p, Vec3 world_point) {
  const Dimensions s = dims(p);
  const Vec3 at = p.transformed ? p.object_from_world.point(world_point) : world_point;
  Vec3 n;
  if (at.y < s.bottom_vertical) {
    n = at * (1.0 / s.bottom);
  } else if (at.y > s.top_vertical) {
    n = Vec3{at.x, at.y - s.bottom, at.z} * (1.0 / s.top);
  } else {   // the spindle: away from its tube's centre circle, on the far side of the axis
    n = Vec3{at.x, at.y - s.vertical, at.z};
    const double horizontal = std::sqrt(n.x * n.x + n.z * n.z);
    n.x += n.x * s.horizontal / horizontal;
    n.z += n.z * s.horizontal / horizontal;
    n = normalize(n);
  }
  if (!p.transformed) return normalize(n);
  return normalize(p.object_from_world.normal_from_inverse(n));
}

bool OvusShape::inside(const Primitive& p, Vec3 world_point) {
  const Dimensions s = dims(p);
  const Vec3 at = p.transformed ? p.object_from_world.point(world_point) : world_point;
  bool in = dot(at, at) < s.bottom * s.bottom;
  const Vec3 from_top{at.x, at.y - s.bottom, at.z};
  if (dot(from_top, from_top) < s.top * s.top) in = true;
  if (at.y > s.bottom_vertical && at.y < s.top_vertical) {
    const double horizontal = std::sqrt(at.x * at.x + at.z * at.z);
    const double off = (horizontal + s.horizontal) * (horizontal + s.horizontal) +
                       (at.y - s.vertical) * (at.y - s.vertical);
    if (off < s.connecting * s.connecting) in = true;
  }
  return in != p.inverse;
}

// Ovus::CalcUV: spherical coordinates about <0, top/2, 0> (the longitude from +x towards +z over 2π, the latitude
// 0.5 + asin(y)/π); <0, 0> at that centre and at the poles' longitude.
std::array<double, 2> OvusShape::uv(const SurfaceHit& hit, Vec3 world_point) {
  const Primitive& p = *hit.leaf;
  const Vec3 at = p.transformed ? p.object_from_world.point(world_point) : world_point;
  Vec3 v{at.x, at.y - p.a.y / 2.0, at.z};
  double len = length(v);
  if (len == 0.0) return {0.0, 0.0};
  v = v * (1.0 / len);
  const double phi = 0.5 + std::asin(v.y) / M_PI;
  double theta = 0.0;
  len = v.x * v.x + v.z * v.z;
  if (len > kEpsilon) {
    len = std::sqrt(len);
    if (v.z == 0.0) theta = v.x > 0 ? 0.0 : M_PI;
    else {
      theta = std::acos(v.x / len);
      if (v.z < 0.0) theta = 2.0 * M_PI - theta;
    }
    theta /= 2.0 * M_PI;
  }
  return {theta, phi};
}

Bounds OvusShape::object_bounds(const Primitive& p) {
  const Dimensions s = dims(p);
  const double w = std::max({s.connecting - s.horizontal, s.bottom, s.top});
  Bounds b;
  b.lo = Vec3{-w, -s.bottom, -w};
  b.hi = Vec3{w, s.bottom + s.top, w};
  return b;
}

}  // namespace povtrace::render::shapes
