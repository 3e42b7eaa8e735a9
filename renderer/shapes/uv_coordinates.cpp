// uv coordinates of a hit for uv_mapping, as POV-Ray 3.7 computes them (source/backend/shape/spheres.cpp
// Sphere::UVCoord, boxes.cpp Box::UVCoord, torus.cpp Torus::CalcUV, mesh.cpp Mesh::UVCoord; scene/objects.cpp
// ObjectBase::UVCoord for every other shape):
// - sphere: in the sphere's own space (every transform undone), u the angle from +x towards +z over 2π, v the
//   latitude 0.5 + asin(y)/π; at the poles (x² + z² ≤ 1e-10) u is 0.
// - box: the point normalised to the box ([0, 1] per axis); each face gets its own region of a 4 × 3 cube layout
//   (−x: u = z/4, v = 1/3 + y/3; +x: u = 3/4 − z/4; −y: u = 1/4 + x/4, v = z/3; +y: v = 1 − z/3; −z: u = 1 − x/4;
//   +z: u = 1/4 + x/4; the four side faces v = 1/3 + y/3).
// - torus: u = 1 − (atan2(z, x) + π)/2π around y, v = (atan2(y, r − R) + π)/2π around the tube.
// - lathe: u around y as the sphere's; v = (segment + w) / segments, at most 1.
// - sor: u around y; v = segment / segments plus the height within the segment's ring over segments; base disc
//   r/r_base − 1, cap disc 2 − r/r_cap.
// - mesh: the triangle's uv_vectors weighted by the point's barycentric coordinates (<0, 0> without uv_vectors).
// - every other shape (plane, cylinder, cone, disc, triangle, polygon, …): the world point's x and y (in the scene's
//   own units when povtrace renders a rescaled twin of it).
#include <algorithm>
#include <cmath>

#include "renderer/geometry.hpp"
#include "renderer/shapes/box.hpp"
#include "renderer/shapes/lathe.hpp"
#include "renderer/shapes/mesh.hpp"
#include "renderer/shapes/sor.hpp"
#include "renderer/shapes/sphere.hpp"
#include "renderer/shapes/torus.hpp"

namespace povtrace::render::shapes {

namespace {
constexpr double kTwoPi = 2.0 * M_PI;

Vec3 object_point(const Primitive& p, Vec3 world_point) {
  return p.transformed ? p.object_from_world.point(world_point) : world_point;
}

// The angle around y from +x toward +z as a fraction of a turn, 0 near the axis (POV-Ray's sphere, lathe and sor
// UVCoord share this).
double turn_around_y(Vec3 d) {
  const double flat2 = d.x * d.x + d.z * d.z;
  if (!(flat2 > tolerance::epsilon)) return 0.0;
  const double flat = std::sqrt(flat2);
  double theta = 0.0;
  if (d.z == 0.0) theta = d.x > 0 ? 0.0 : M_PI;
  else {
    theta = std::acos(d.x / flat);
    if (d.z < 0.0) theta = kTwoPi - theta;
  }
  return theta / kTwoPi;
}

}  // namespace

std::array<double, 2> SphereShape::uv(const SurfaceHit& hit, Vec3 world_point) {
  const Primitive& p = *hit.leaf;
  Vec3 d = object_point(p, world_point) - p.a;
  const double len = length(d);
  if (len == 0.0) return {0.0, 0.0};
  d = d / len;
  const double v = 0.5 + std::asin(d.y) / M_PI;
  return {turn_around_y(d), v};
}

// A lathe: u around y, v the segment index plus the segment parameter w, over the number of segments (at most 1).
std::array<double, 2> LatheShape::uv(const SurfaceHit& hit, Vec3 world_point) {
  const auto& d = static_cast<const LatheData&>(*hit.leaf->data);
  const double v = (hit.u + double(hit.element)) / double(d.segments.size());
  return {turn_around_y(object_point(*hit.leaf, world_point)), std::min(v, 1.0)};
}

// A sor: u around y; v the height within the segment's ring, over the number of segments; on the base disc it runs
// from −1 at the axis to 0 at the rim, on the cap from 2 to 1 (POV-Ray's Sor::UVCoord).
std::array<double, 2> SorShape::uv(const SurfaceHit& hit, Vec3 world_point) {
  const auto& d = static_cast<const SorData&>(*hit.leaf->data);
  const Vec3 q = object_point(*hit.leaf, world_point);
  const double u = turn_around_y(q);
  const double r = std::sqrt(q.x * q.x + q.z * q.z);
  if (hit.element == base_element) return {u, r / std::sqrt(d.base_radius2) - 1.0};
  if (hit.element == cap_element) return {u, 2.0 - r / std::sqrt(d.cap_radius2)};
  const Ring& ring = d.rings[hit.element];
  const double per_segment = 1.0 / double(d.segments.size());
  return {u, (q.y - ring.h1) / (ring.h2 - ring.h1) * per_segment + double(hit.element) * per_segment};
}

// The face the point lies on, as box_normal picks it: the nearest of the six planes (axis, and the high side).
std::array<double, 2> BoxShape::uv(const SurfaceHit& hit, Vec3 world_point) {
  const Primitive& p = *hit.leaf;
  const Vec3 q = object_point(p, world_point);
  int axis = 0;
  bool high = false;
  double best = std::abs(q.x - p.a.x);
  for (int k = 0; k < 3; ++k) {
    if (const double d = std::abs(q[k] - p.a[k]); d < best) { best = d; axis = k; high = false; }
    if (const double d = std::abs(q[k] - p.b[k]); d < best) { best = d; axis = k; high = true; }
  }
  const Vec3 diff = p.b - p.a;
  const Vec3 n{(q.x - p.a.x) / diff.x, (q.y - p.a.y) / diff.y, (q.z - p.a.z) / diff.z};
  const double side_v = 1.0 / 3.0 + n.y / 3.0;
  switch (axis * 2 + (high ? 1 : 0)) {
    case 0: return {n.z / 4.0, side_v};
    case 1: return {3.0 / 4.0 - n.z / 4.0, side_v};
    case 2: return {1.0 / 4.0 + n.x / 4.0, n.z / 3.0};
    case 3: return {1.0 / 4.0 + n.x / 4.0, 3.0 / 3.0 - n.z / 3.0};
    case 4: return {1.0 - n.x / 4.0, side_v};
    default: return {1.0 / 4.0 + n.x / 4.0, side_v};
  }
}

std::array<double, 2> TorusShape::uv(const SurfaceHit& hit, Vec3 world_point) {
  const Primitive& p = *hit.leaf;
  const Vec3 q = object_point(p, world_point);
  const double u = 1.0 - (std::atan2(q.z, q.x) + M_PI) / kTwoPi;
  const double r = std::sqrt(q.x * q.x + q.z * q.z) - p.a.x;   // p.a.x: the major radius
  const double v = (std::atan2(q.y, r) + M_PI) / kTwoPi;
  return {u, v};
}

std::array<double, 2> MeshShape::uv(const SurfaceHit& hit, Vec3) {
  const MeshData& data = *static_cast<const MeshShapeData&>(*hit.leaf->data).data;
  if (data.face_uvs.empty()) return {0.0, 0.0};
  const std::uint32_t* uv = &data.face_uvs[3 * std::size_t(hit.element)];
  const double w[3] = {1.0 - hit.u - hit.v, hit.u, hit.v};
  std::array<double, 2> out{0.0, 0.0};
  for (int k = 0; k < 3; ++k) {
    out[0] += w[k] * data.uvs[2 * std::size_t(uv[k])];
    out[1] += w[k] * data.uvs[2 * std::size_t(uv[k]) + 1];
  }
  return out;
}

}  // namespace povtrace::render::shapes
