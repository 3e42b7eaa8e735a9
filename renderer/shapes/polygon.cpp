// Polygon.
//
// SDL: `polygon { n, P1, …, Pn }` (POV-Ray 3.7 reference "Polygon"). No inside.
//
// POV-Ray behaviour reproduced (facts read from source/backend/shape/polygon.cpp, 3.7-stable):
// - The parser puts the points into the polygon's plane frame (parser/objects/meshes.cpp); the primitive's object space
//   is that frame, so the polygon is z = 0 there. The world ray is carried into it and normalised (length L); no
//   hit when |d_z| < 1e-10; the object-space depth must satisfy 1e-8 ≤ depth ≤ MAX_DISTANCE (1e7) and the reported
//   world depth is depth / L.
// - Inclusion: the even-odd crossing test of a +x ray from the hit point, with an edge counted when its endpoints'
//   y straddle the point's (y ≥ ty on one side only) and the crossing lies at or right of it. Sub-polygons are
//   separate loops: after a vertex equal to the loop's first one, the walk starts the next loop.
// - Normal: (0, 0, 1) carried to world space by the inverse transpose, normalised. Degenerate polygons are never hit.
#include <cmath>

#include "renderer/shapes/triangle_shapes.hpp"
#include "renderer/shapes/polygon.hpp"

namespace povtrace::render::shapes {

namespace {
constexpr double depth_tolerance = 1e-8;
constexpr double zero_tolerance = 1e-10;

const PolygonData& data_of(const Primitive& p) { return static_cast<const PolygonData&>(*p.data); }

bool in_polygon(const std::vector<std::array<double, 2>>& pts, double tx, double ty) {
  const std::size_t n = pts.size();
  const std::array<double, 2>* v0 = &pts[0];
  const std::array<double, 2>* v1 = &pts[1];
  const std::array<double, 2>* first = v0;
  bool y0 = (*v0)[1] >= ty;
  bool inside = false;
  for (std::size_t i = 1; i < n;) {
    const bool y1 = (*v1)[1] >= ty;
    if (y0 != y1) {
      const bool right = ((*v1)[1] - ty) * ((*v0)[0] - (*v1)[0]) >= ((*v1)[0] - tx) * ((*v0)[1] - (*v1)[1]);
      if (right == y1) inside = !inside;
    }
    if (i + 2 < n && (*v1)[0] == (*first)[0] && (*v1)[1] == (*first)[1]) {
      // This loop is closed: the next point starts the next sub-polygon.
      v0 = &pts[++i];
      v1 = &pts[++i];
      y0 = (*v0)[1] >= ty;
      first = v0;
    } else {
      v0 = v1;
      if (++i < n) v1 = &pts[i];
      y0 = y1;
    }
  }
  return inside;
}
}  // namespace

void set_up_polygon(Primitive& p, const Polygon& polygon) {
  auto data = std::make_shared<PolygonData>();
  data->points = polygon.points;
  data->degenerate = polygon.degenerate || polygon.points.size() < 3;
  if (!data->degenerate) {
    p.world_from_object = polygon.world_from_plane * p.world_from_object;
    p.object_from_world = p.world_from_object.inverse();
    p.transformed = true;
  }
  p.data = std::move(data);
}

Intersections PolygonShape::intersect(const Primitive& p, const Ray& ray) {
  Intersections out;
  const PolygonData& d = data_of(p);
  if (d.degenerate) return out;
  const Vec3 origin = p.object_from_world.point(ray.origin);
  Vec3 direction = p.object_from_world.vector(ray.direction);
  const double len = length(direction);
  direction *= 1.0 / len;
  if (std::fabs(direction.z) < zero_tolerance) return out;
  const double depth = -origin.z / direction.z;
  if (depth < depth_tolerance || depth > tolerance::max_distance) return out;
  if (!in_polygon(d.points, origin.x + depth * direction.x, origin.y + depth * direction.y)) return out;
  out.t[out.count++] = depth / len;
  return out;
}

Vec3 PolygonShape::normal(const Primitive& p, Vec3) { return normalize(p.object_from_world.normal_from_inverse({0, 0, 1})); }

Bounds PolygonShape::object_bounds(const Primitive& p) {
  const PolygonData& d = data_of(p);
  Bounds b;
  if (d.degenerate) return b;
  for (const auto& q : d.points) b.extend(Vec3{q[0], q[1], 0});
  return b;
}

Primitive PolygonShape::build(const Polygon& polygon, const Matrix& world_from_object) {
  Primitive p = placed_primitive(ShapeType::polygon, world_from_object);
  set_up_polygon(p, polygon);
  return p;
}

}  // namespace povtrace::render::shapes
