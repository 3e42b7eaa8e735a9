// Height field.
//
// SDL: `height_field { png "file" [smooth] [water_level W] object_modifiers... }` (POV-Ray 3.7 reference "Height
// Field"): two triangles per cell of the sample grid (height_field_build.cpp reads the samples and places the grid
// in the unit cube). Primitive: data = HeightFieldData; SurfaceHit::element = 2·cell + (0 lower, 1 upper triangle).
//
// POV-Ray behaviour reproduced here (facts read from source/backend/shape/hfield.cpp and boxes.cpp Box::Intersect,
// 3.7-stable):
// - The world ray goes to grid space *without* normalising its direction, so every depth is a world distance.
// - The ray is clipped to the box [0, w − 1] × [bottom, top] × [0, h − 1] (from depth 0; no hit when the exit is
//   below 1e-6); an entry below 1e-6 is raised to 1e-6. Only the cells the clipped ray passes over are tested.
//   (POV-Ray walks them with a Bresenham-style DDA in blocks and culls by height; both only skip cells and
//   triangles the ray cannot meet.) The walk ends at the first cell with a hit, as POV-Ray's does for a height
//   field that is no CSG child: the tolerances below let a triangle's plane be hit up to 1e-4 beyond its cell,
//   and a nearer such hit in the next cell must not win over the cell the ray is in. Inside a CSG node (a child,
//   or clipped or bounded) the walk goes on over every cell, as POV-Ray's does for IS_CHILD_OBJECT, and the node
//   filters the hits (POV-Ray applies a height field's own clip inside the walk, cell by cell: the first cell
//   with a hit that survives the clip ends it).
// - Cell (x, z) with heights y1 = H(x, z), y2 = H(x + 1, z), y3 = H(x, z + 1), y4 = H(x + 1, z + 1) holds the lower
//   triangle through (x, y1, z) with normal (y1 − y2, 1, y1 − y3) and the upper one through (x + 1, y4, z + 1) with
//   normal (y3 − y4, 1, y2 − y4). A ray within 1e-10 of parallel to a triangle's plane misses it; a plane hit
//   counts when its depth is within the clipped span (inclusive) and its offsets s, t from the cell corner satisfy
//   s, t >= −1e-4, s + t <= 1.0001 (lower) or s, t <= 1.0001, s + t >= 0.9999 (upper).
// - Normal: without `smooth`, the hit triangle's normal (carried to world by the inverse transpose, normalised);
//   with `smooth`, the four vertex normals of the cell containing the point (each carried to world and
//   normalised) interpolated bilinearly, then normalised.
// - Inside: outside the grid's x/z span (upper bounds excluded) or at or above the box top is outside; below the
//   box bottom is inside; otherwise below the plane of the triangle containing the point (heights raised to the
//   box bottom) is inside. `inverse` negates the test.
// - Bounds: the clipping box carried to world.
#include <cmath>
#include <limits>

#include "renderer/shapes/height_field.hpp"
#include "renderer/shapes/many_roots.hpp"

namespace povtrace::render::shapes {

namespace {
constexpr double hfield_tolerance = 1e-6;   // hfield.cpp HFIELD_TOLERANCE
constexpr double box_depth = 1e-6;          // boxes.cpp DEPTH_TOLERANCE

const HeightFieldData& data_of(const Primitive& p) { return static_cast<const HeightFieldData&>(*p.data); }

// Box::Intersect's span of the ray inside [lo, hi], from depth 0 on.
bool clip(Vec3 o, Vec3 d, Vec3 lo, Vec3 hi, double& t_min, double& t_max) {
  t_min = 0.0;
  t_max = tolerance::bound_huge;
  for (int a = 0; a < 3; ++a) {
    if (std::abs(d[a]) <= tolerance::epsilon) {
      if (o[a] < lo[a] || o[a] > hi[a]) return false;
      continue;
    }
    double near = (lo[a] - o[a]) / d[a], far = (hi[a] - o[a]) / d[a];
    if (d[a] < 0.0) std::swap(near, far);
    if (far < t_min) return false;
    t_max = std::min(t_max, far);
    if (near >= t_min) {
      if (near > t_max) return false;
      t_min = near;
    }
  }
  return t_max >= box_depth;
}

void triangle_hits(const HeightFieldData& f, int x, int z, Vec3 o, Vec3 d, double lo, double hi, RootList& out) {
  const double y1 = f.height(x, z), y2 = f.height(x + 1, z), y3 = f.height(x, z + 1), y4 = f.height(x + 1, z + 1);
  const auto cell = static_cast<std::uint32_t>(z * (f.width - 1) + x) * 2;
  for (int upper = 0; upper < 2; ++upper) {
    const Vec3 corner = upper ? Vec3{x + 1.0, y4, z + 1.0} : Vec3{double(x), y1, double(z)};
    const Vec3 n = upper ? Vec3{y3 - y4, 1.0, y2 - y4} : Vec3{y1 - y2, 1.0, y1 - y3};
    const double along = dot(n, d);
    if (!(along > tolerance::epsilon || along < -tolerance::epsilon)) continue;
    const double depth = dot(n, corner - o) / along;
    if (!(depth >= lo && depth <= hi)) continue;
    const double s = o.x + depth * d.x - x, t = o.z + depth * d.z - z;
    const bool within = upper ? s <= 1.0001 && t <= 1.0001 && s + t >= 0.9999
                              : s >= -0.0001 && t >= -0.0001 && s + t <= 1.0001;
    if (within) out.push_back(Root{depth, cell + static_cast<std::uint32_t>(upper)});
  }
}

int clamp_cell(double v, int last) {
  const double f = std::floor(v);
  return !(f >= 0.0) ? 0 : f > last ? last : static_cast<int>(f);   // NaN: 0, never an int cast of it
}

// Where the ray next crosses a cell boundary along one axis, and the depth between crossings.
struct AxisWalk {
  int step = 0;
  double next = std::numeric_limits<double>::infinity(), delta = 0;
  AxisWalk(double o, double d, int cell) {
    if (d > 0.0) step = 1, next = (cell + 1 - o) / d, delta = 1.0 / d;
    else if (d < 0.0) step = -1, next = (cell - o) / d, delta = -1.0 / d;
  }
};
}  // namespace

void HeightFieldShape::roots(const Primitive& p, const Ray& ray, RootList& out) {
  const HeightFieldData& f = data_of(p);
  const Vec3 o = p.object_from_world.point(ray.origin), d = p.object_from_world.vector(ray.direction);
  double lo = 0, hi = 0;
  if (!clip(o, d, Vec3{0, f.bottom, 0}, Vec3{f.width - 1.0, f.top, f.depth - 1.0}, lo, hi)) return;
  if (lo < hfield_tolerance) {
    lo = hfield_tolerance;
    if (lo > hi) return;
  }
  const Vec3 start = o + d * lo;
  const int last_x = f.width - 2, last_z = f.depth - 2;
  int x = clamp_cell(start.x, last_x), z = clamp_cell(start.z, last_z);
  AxisWalk wx(o.x, d.x, x), wz(o.z, d.z, z);
  const std::size_t before = out.size();
  while (true) {
    triangle_hits(f, x, z, o, d, lo, hi, out);
    if (out.size() != before && !p.csg_child) return;   // the first cell with a hit ends the walk (see the header)
    AxisWalk& w = wx.next < wz.next ? wx : wz;
    int& cell = &w == &wx ? x : z;
    if (w.next > hi) return;
    cell += w.step;
    if (cell < 0 || cell > (&w == &wx ? last_x : last_z)) return;
    w.next += w.delta;
  }
}


Vec3 HeightFieldShape::normal(const Primitive& p, Vec3 world_point) {
  const HeightFieldData& f = data_of(p);
  const Vec3 q = p.object_from_world.point(world_point);
  // POV-Ray truncates and caps at the last cell; for the points of hits (x, z >= −1e-4) flooring and clamping agree.
  const int px = clamp_cell(q.x, f.width - 2), pz = clamp_cell(q.z, f.depth - 2);
  const double x = q.x - px, z = q.z - pz;
  if (!f.smooth) {
    const bool upper = x + z > 1.0;
    return normal_at(p, static_cast<std::uint32_t>(pz * (f.width - 1) + px) * 2 + upper, world_point);
  }
  Vec3 n[4];
  for (int k = 0; k < 4; ++k) {
    const auto& s = f.normals[static_cast<std::size_t>(pz + k / 2) * f.width + px + k % 2];
    n[k] = p.object_from_world.normal_from_inverse(Vec3{double(s[0]), double(s[1]), double(s[2])});
    n[k] = n[k] * (1.0 / length(n[k]));
  }
  const double u = 1.0 - x, v = 1.0 - z;
  const Vec3 r = (n[0] * u + n[1] * x) * v + (n[2] * u + n[3] * x) * z;
  return r * (1.0 / length(r));
}

Vec3 HeightFieldShape::normal_at(const Primitive& p, std::uint32_t element, Vec3 world_point) {
  const HeightFieldData& f = data_of(p);
  if (f.smooth) return HeightFieldShape::normal(p, world_point);
  const int cell = static_cast<int>(element / 2), x = cell % (f.width - 1), z = cell / (f.width - 1);
  const double y1 = f.height(x, z), y2 = f.height(x + 1, z), y3 = f.height(x, z + 1), y4 = f.height(x + 1, z + 1);
  const Vec3 n = element % 2 ? Vec3{y3 - y4, 1.0, y2 - y4} : Vec3{y1 - y2, 1.0, y1 - y3};
  const Vec3 w = p.object_from_world.normal_from_inverse(n);
  return w * (1.0 / length(w));
}

bool HeightFieldShape::inside(const Primitive& p, Vec3 world_point) {
  const HeightFieldData& f = data_of(p);
  const Vec3 q = p.object_from_world.point(world_point);
  if (q.x < 0.0 || q.x >= f.width - 1.0 || q.z < 0.0 || q.z >= f.depth - 1.0 || q.y >= f.top) return p.inverse;
  if (q.y < f.bottom) return !p.inverse;
  int px = static_cast<int>(q.x), pz = static_cast<int>(q.z);
  const auto h = [&](int x, int z) { return std::max(f.height(x, z), f.bottom); };
  Vec3 corner, n;
  if (q.x - px + q.z - pz < 1.0) {
    const double y1 = h(px, pz);
    corner = Vec3{double(px), y1, double(pz)};
    n = Vec3{y1 - h(px + 1, pz), 1.0, y1 - h(px, pz + 1)};
  } else {
    px = static_cast<int>(std::ceil(q.x));
    pz = static_cast<int>(std::ceil(q.z));
    const double y1 = h(px, pz);
    corner = Vec3{double(px), y1, double(pz)};
    n = Vec3{h(px - 1, pz) - y1, 1.0, h(px, pz - 1) - y1};
  }
  return (dot(q, n) < dot(corner, n)) != p.inverse;
}

Bounds HeightFieldShape::object_bounds(const Primitive& p) {
  const HeightFieldData& f = data_of(p);
  return Bounds{Vec3{0, f.bottom, 0}, Vec3{f.width - 1.0, f.top, f.depth - 1.0}};
}

}  // namespace povtrace::render::shapes
