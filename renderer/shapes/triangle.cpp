// Triangle and smooth triangle.
//
// SDL: `triangle { P1, P2, P3 }`, `smooth_triangle { P1, N1, P2, N2, P3, N3 }` (POV-Ray 3.7 reference "Triangle
// and Smooth_triangle"). No inside.
//
// POV-Ray behaviour reproduced (facts read from source/backend/shape/triangle.cpp, 3.7-stable):
// - Transforms move the vertices themselves (Triangle::Transform), and smooth normals by the inverse transpose, so
//   the triangle lives in world space: the depth is the world distance along the unit ray, kept when
//   DEPTH_TOLERANCE (1e-6) ≤ depth ≤ MAX_DISTANCE (1e7).
// - Degenerate triangles (zero area; for smooth triangles also normals not all strictly on one side of the face,
//   re-checked after the transform as Compute_Triangle does) are never hit.
// - Smooth normal: N1 + u·(N2 − N1 + v·(N3 − N2)) with POV-Ray's (u, v) — the barycentric interpolation of the
//   three vertex normals — then normalised. povtrace normalises the transformed vertex normals first (POV-Ray's
//   Scale does, its Transform of a general matrix does not: a sheared smooth triangle may shade slightly apart).
// - Where POV-Ray tests the three edges in the plane of the dominant axis, povtrace uses the watertight test of
//   watertight.hpp: identical away from edges, and rays through an edge shared with another triangle hit one.
#include <cmath>

#include "renderer/shapes/triangle_shapes.hpp"
#include "renderer/shapes/watertight.hpp"
#include "renderer/shapes/triangle.hpp"

namespace povtrace::render::shapes {

namespace {
constexpr double depth_tolerance = 1e-6;

const TriangleData& data_of(const Primitive& p) { return static_cast<const TriangleData&>(*p.data); }

// Barycentric weights of a point in the triangle's plane (weights of corners 2 and 3; corner 1 has the rest).
void barycentric(const std::array<Vec3, 3>& c, Vec3 point, double& w2, double& w3) {
  const Vec3 n = cross(c[1] - c[0], c[2] - c[0]);
  const double n2 = dot(n, n);
  w2 = dot(n, cross(point - c[0], c[2] - c[0])) / n2;
  w3 = dot(n, cross(c[1] - c[0], point - c[0])) / n2;
}
}  // namespace

void set_up_triangle(Primitive& p, const Triangle& triangle) {
  auto data = std::make_shared<TriangleData>();
  const Matrix world = p.world_from_object;
  const Matrix inverse = world.inverse();
  for (int k = 0; k < 3; ++k) data->corners[k] = world.point(triangle.corners[k]);
  const Vec3 face = cross(data->corners[0] - data->corners[1], data->corners[2] - data->corners[1]);
  data->degenerate = triangle.degenerate || length(face) == 0.0;
  if (triangle.normals && !data->degenerate) {
    data->smooth = true;
    int positive = 0, negative = 0;
    for (int k = 0; k < 3; ++k) {
      data->normals[k] = normalize(inverse.normal_from_inverse((*triangle.normals)[k]));
      positive += dot(face, data->normals[k]) > 0.0;
      negative += dot(face, data->normals[k]) < 0.0;
    }
    data->degenerate = positive != 3 && negative != 3;
  }
  p.transformed = false;   // the transform is in the corners now
  p.world_from_object = Matrix::identity();
  p.object_from_world = Matrix::identity();
  p.data = std::move(data);
}

Intersections TriangleShape::intersect(const Primitive& p, const Ray& ray) {
  Intersections out;
  const TriangleData& d = data_of(p);
  if (d.degenerate) return out;
  TriangleHit hit;
  if (!intersect_watertight(ShearedRay(ray), d.corners[0], d.corners[1], d.corners[2], hit)) return out;
  if (hit.t >= depth_tolerance && hit.t <= tolerance::max_distance) out.t[out.count++] = hit.t;
  return out;
}

Vec3 TriangleShape::normal(const Primitive& p, Vec3 world_point) {
  const TriangleData& d = data_of(p);
  if (!d.smooth) return normalize(cross(d.corners[0] - d.corners[1], d.corners[2] - d.corners[1]));
  double w2 = 0, w3 = 0;
  barycentric(d.corners, world_point, w2, w3);
  return normalize(d.normals[0] * (1.0 - w2 - w3) + d.normals[1] * w2 + d.normals[2] * w3);
}

// POV-Ray's Compute_BBox: the corners' box grown by EPSILON.
Bounds TriangleShape::world_bounds(const Primitive& p) {
  const TriangleData& d = data_of(p);
  Bounds b;
  for (const Vec3& c : d.corners) b.extend(c);
  const Vec3 e{tolerance::epsilon, tolerance::epsilon, tolerance::epsilon};
  return Bounds{b.lo - e, b.hi + e};
}

Primitive TriangleShape::build(const Triangle& triangle, const Matrix& world_from_object) {
  Primitive p = placed_primitive(ShapeType::triangle, world_from_object);
  set_up_triangle(p, triangle);
  return p;
}

}  // namespace povtrace::render::shapes
