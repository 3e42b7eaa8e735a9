// bicubic_patch: a cubic Bézier patch, subdivided into flat quads as POV-Ray 3.7 does (written anew from the facts of
// source/backend/shape/bezier.cpp, 3.7-stable; docs/issue21-bicubic-patch.md):
// - The net is halved by de Casteljau at ½ (each midpoint 0.5·(a + b)), across the rows (u) and along them (v), until
//   it is flat enough (the largest distance of its 16 points from the plane of three corners below `flatness`,
//   strictly) or u_steps and v_steps halvings are done; when one direction's steps are used up only the other is
//   halved. The four children of a double split come in the order (u low, v low), (u low, v high), (u high, v low),
//   (u high, v high). Types 0 and 1 make the same pieces (POV-Ray repeats the subdivision per ray for type 0): one
//   tree serves both.
// - Each node is bounded by a sphere around the mean of its net; a ray passes it when it starts inside or its
//   closest approach is within the radius (+1e-10), whichever side of the origin the sphere lies.
// - A leaf quad is two triangles through its corners, split along (u0, v0)–(u1, v1); each triangle met at a depth of
//   at least 1e-5 is a hit, edges included, found with POV-Ray's inverted edge matrix (MInvers3). All are reported:
//   of equal depths the last found wins (POV-Ray's stack of hits).
// - The normal blends the whole patch's unit normals (∂P/∂u × ∂P/∂v, or <1, 0, 0> where that vanishes) at the
//   triangle's corners by the hit's weights; texture uv is the uv_vectors quad at (v, u).
#include "renderer/shapes/bicubic_patch.hpp"

#include <cmath>
#include <limits>

namespace povtrace::render {

namespace {
constexpr double kBezierEpsilon = 1e-10;     // BEZIER_EPSILON
constexpr double kBezierTolerance = 1e-5;    // BEZIER_TOLERANCE: the nearest depth a triangle reports
constexpr double kEpsilon = 1e-10;           // EPSILON

using Net = std::array<std::array<Vec3, 4>, 4>;   // net[i][j]: u along i, v along j

Vec3 half(Vec3 a, Vec3 b) { return {0.5 * (a.x + b.x), 0.5 * (a.y + b.y), 0.5 * (a.z + b.z)}; }

// De Casteljau at ½ of one cubic: the low and the high half.
void halve(const std::array<Vec3, 4>& q, std::array<Vec3, 4>& low, std::array<Vec3, 4>& high) {
  const Vec3 a = half(q[0], q[1]);
  const Vec3 h = half(q[1], q[2]);
  const Vec3 b = half(a, h);
  const Vec3 c = half(q[2], q[3]);
  const Vec3 d = half(h, c);
  const Vec3 m = half(b, d);
  low = {q[0], a, b, m};
  high = {m, d, c, q[3]};
}

// Halves every column (u, the first index): POV-Ray's bezier_split_left_right.
void split_u(const Net& net, Net& low, Net& high) {
  for (std::size_t j = 0; j < 4; ++j) {
    std::array<Vec3, 4> lo, hi;
    halve({net[0][j], net[1][j], net[2][j], net[3][j]}, lo, hi);
    for (std::size_t k = 0; k < 4; ++k) {
      low[k][j] = lo[k];
      high[k][j] = hi[k];
    }
  }
}

// Halves every row (v, the second index): POV-Ray's bezier_split_up_down.
void split_v(const Net& net, Net& low, Net& high) {
  for (std::size_t i = 0; i < 4; ++i) halve(net[i], low[i], high[i]);
}

double distance_between(Vec3 a, Vec3 b) { return std::sqrt(dot(a - b, a - b)); }

// POV-Ray's determine_subpatch_flatness: the largest distance of the net's points from the plane of three corners,
// or −1 when those corners do not make a plane.
double flatness_of(const Net& net) {
  Vec3 a = net[0][0], b = net[0][3], c;
  if (std::fabs(distance_between(a, b)) < kEpsilon) {   // the u = 0 edge is one point: use the far corner
    b = net[3][3];
    if (std::fabs(distance_between(a, b)) < kEpsilon) return -1.0;
    c = net[3][0];
  } else {
    c = net[3][0];
  }
  if (std::fabs(distance_between(b, c)) < kEpsilon) return -1.0;
  const Vec3 e1 = a - b, e2 = c - b;
  Vec3 n = cross(e1, e2);
  const double n2 = dot(n, n);
  if (n2 <= kBezierEpsilon * dot(e1, e1) * dot(e2, e2)) return -1.0;
  n = n / std::sqrt(n2);
  const double d = 0.0 - dot(n, a);
  const double n_length = std::sqrt(dot(n, n));
  double flatness = 0.0;
  for (const auto& row : net)
    for (const Vec3& p : row) {
      const double distance = n_length < kEpsilon ? 0.0 : std::fabs((dot(p, n) + d) / n_length);
      if (distance > flatness) flatness = distance;
    }
  return flatness;
}

// The sphere around the mean of the net's points through the farthest one (radius squared).
void bounding_sphere(const Net& net, Vec3& centre, double& radius2) {
  double x = 0, y = 0, z = 0;
  for (const auto& row : net)
    for (const Vec3& p : row) {
      x += p.x;
      y += p.y;
      z += p.z;
    }
  centre = {x / 16.0, y / 16.0, z / 16.0};
  radius2 = 0.0;
  for (const auto& row : net)
    for (const Vec3& p : row) {
      const double dx = p.x - centre.x, dy = p.y - centre.y, dz = p.z - centre.z;
      const double r2 = dx * dx + dy * dy + dz * dz;
      if (r2 > radius2) radius2 = r2;
    }
}

// The whole patch's unit normal at (u, v): ∂P/∂u × ∂P/∂v from the Bernstein polynomials and their derivatives,
// summed over the net in POV-Ray's order (bezier_value); <1, 0, 0> where it vanishes.
Vec3 patch_normal(const Net& net, double u0, double v0) {
  static constexpr double binomial[] = {1.0, 3.0, 3.0, 1.0};
  double u[4], uu[4], v[4], vv[4], du[4], duu[4], dv[4], dvv[4];
  u[0] = uu[0] = v[0] = vv[0] = 1.0;
  du[0] = duu[0] = dv[0] = dvv[0] = 0.0;
  for (int i = 1; i < 4; ++i) {
    u[i] = u[i - 1] * u0;
    uu[i] = uu[i - 1] * (1.0 - u0);
    v[i] = v[i - 1] * v0;
    vv[i] = vv[i - 1] * (1.0 - v0);
    du[i] = i * u[i - 1];
    duu[i] = -i * uu[i - 1];
    dv[i] = i * v[i - 1];
    dvv[i] = -i * vv[i - 1];
  }
  Vec3 along_u, along_v;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      const double c = binomial[i] * binomial[j];
      const double ut = u[i] * uu[3 - i];
      const double vt = v[j] * vv[3 - j];
      const Vec3 p = net[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)];
      const double tu = c * vt * (du[i] * uu[3 - i] + u[i] * duu[3 - i]);
      along_u = {along_u.x + tu * p.x, along_u.y + tu * p.y, along_u.z + tu * p.z};
      const double tv = c * ut * (dv[j] * vv[3 - j] + v[j] * dvv[3 - j]);
      along_v = {along_v.x + tv * p.x, along_v.y + tv * p.y, along_v.z + tv * p.z};
    }
  const Vec3 n = cross(along_u, along_v);
  const double t = dot(n, n);
  if (t > kBezierEpsilon * dot(along_u, along_u) * dot(along_v, along_v)) return n * (1.0 / std::sqrt(t));
  return {1, 0, 0};
}

class TreeBuilder {
 public:
  TreeBuilder(const BicubicPatch& patch, const Net& whole, BicubicPatchData& out)
      : patch_(patch), whole_(whole), out_(out) {}

  // Fills nodes[index] with the sub-net over [u0, u1] × [v0, v1] at `depth` (POV-Ray's bezier_tree_builder).
  void build(std::size_t index, const Net& net, double u0, double u1, double v0, double v1, int depth) {
    bounding_sphere(net, out_.nodes[index].centre, out_.nodes[index].radius2);
    const double flatness = flatness_of(net);
    const bool flat = flatness >= 0.0 && flatness < patch_.flatness;
    const bool split_along_u = depth < patch_.u_steps, split_along_v = depth < patch_.v_steps;
    if (flat || (!split_along_u && !split_along_v)) return make_leaf(index, net, u0, u1, v0, v1);
    const double um = (u0 + u1) / 2.0, vm = (v0 + v1) / 2.0;
    if (!split_along_u) {
      Net low, high;
      split_v(net, low, high);
      const std::size_t first = add_children(index, 2);
      build(first, low, u0, u1, v0, vm, depth + 1);
      build(first + 1, high, u0, u1, vm, v1, depth + 1);
      return;
    }
    Net left, right;
    split_u(net, left, right);
    if (!split_along_v) {
      const std::size_t first = add_children(index, 2);
      build(first, left, u0, um, v0, v1, depth + 1);
      build(first + 1, right, um, u1, v0, v1, depth + 1);
      return;
    }
    Net left_low, left_high, right_low, right_high;
    split_v(left, left_low, left_high);
    split_v(right, right_low, right_high);
    const std::size_t first = add_children(index, 4);
    build(first, left_low, u0, um, v0, vm, depth + 1);
    build(first + 1, left_high, u0, um, vm, v1, depth + 1);
    build(first + 2, right_low, um, u1, v0, vm, depth + 1);
    build(first + 3, right_high, um, u1, vm, v1, depth + 1);
  }

 private:
  std::size_t add_children(std::size_t index, std::uint8_t count) {
    const std::size_t first = out_.nodes.size();
    out_.nodes[index].first = static_cast<std::uint32_t>(first);
    out_.nodes[index].children = count;
    out_.nodes.resize(first + count);
    return first;
  }

  void make_leaf(std::size_t index, const Net& net, double u0, double u1, double v0, double v1) {
    BicubicPatchData::Leaf leaf;
    leaf.corner = {net[0][0], net[0][3], net[3][3], net[3][0]};
    leaf.u0 = u0;
    leaf.u1 = u1;
    leaf.v0 = v0;
    leaf.v1 = v1;
    leaf.normal = {patch_normal(whole_, u0, v0), patch_normal(whole_, u0, v1), patch_normal(whole_, u1, v1),
                   patch_normal(whole_, u1, v0)};
    out_.nodes[index].first = static_cast<std::uint32_t>(out_.leaves.size());
    out_.nodes[index].children = 0;
    out_.leaves.push_back(leaf);
  }

  const BicubicPatch& patch_;
  const Net& whole_;
  BicubicPatchData& out_;
};
}  // namespace

std::shared_ptr<BicubicPatchData> bicubic_patch_data(const BicubicPatch& patch, const Matrix& world_from_object) {
  auto data = std::make_shared<BicubicPatchData>();
  const bool moved = !(world_from_object == Matrix{});
  Net net;
  for (std::size_t k = 0; k < 16; ++k) {
    const Vec3 p = moved ? world_from_object.point(patch.points[k]) : patch.points[k];
    net[k / 4][k % 4] = p;
    data->bounds.extend(p);
  }
  data->uv_vectors = patch.uv_vectors;
  data->nodes.resize(1);
  TreeBuilder(patch, net, *data).build(0, net, 0.0, 1.0, 0.0, 1.0, 0);
  return data;
}

}  // namespace povtrace::render

namespace povtrace::render::shapes {

namespace {
const BicubicPatchData& data_of(const Primitive& p) { return static_cast<const BicubicPatchData&>(*p.data); }

// POV-Ray's spherical_bounds_check (radius squared).
bool passes_sphere(const Ray& ray, Vec3 centre, double radius2) {
  const double x = centre.x - ray.origin.x, y = centre.y - ray.origin.y, z = centre.z - ray.origin.z;
  const double dist1 = x * x + y * y + z * z;
  if (dist1 < radius2) return true;
  double dist2 = x * ray.direction.x + y * ray.direction.y + z * ray.direction.z;
  dist2 *= dist2;
  return dist2 > 0 && (dist1 - dist2) <= radius2 + kBezierEpsilon;
}

struct TriangleHit {
  double t = 0, a = 0, b = 0;
};

// POV-Ray's intersect_subpatch for the triangle w0 w1 w2: the edges' matrix inverted by cofactors (MInvers3, which
// gives the inverse's transpose: row k is the dual of edge k), the depth along its third row, the weights a and b of
// w1 and w2 along the first two.
std::optional<TriangleHit> hit_triangle(const Ray& ray, Vec3 w0, Vec3 w1, Vec3 w2) {
  const Vec3 b0 = w1 - w0, b1 = w2 - w0;
  Vec3 b2 = cross(b0, b1);
  const double n2 = dot(b2, b2);
  if (n2 <= kBezierEpsilon * dot(b1, b1) * dot(b0, b0)) return std::nullopt;
  b2 = b2 * (1.0 / std::sqrt(n2));
  const double m[3][3] = {{b0.x, b0.y, b0.z}, {b1.x, b1.y, b1.z}, {b2.x, b2.y, b2.z}};
  const double det = m[0][0] * m[1][1] * m[2][2] + m[0][1] * m[1][2] * m[2][0] + m[0][2] * m[1][0] * m[2][1] -
                     m[0][2] * m[1][1] * m[2][0] - m[0][0] * m[1][2] * m[2][1] - m[0][1] * m[1][0] * m[2][2];
  if (std::fabs(det) < 1.0e-10) return std::nullopt;
  const double s = 1.0 / det;
  const Vec3 e0{(m[1][1] * m[2][2] - m[1][2] * m[2][1]) * s, -(m[1][0] * m[2][2] - m[1][2] * m[2][0]) * s,
                (m[1][0] * m[2][1] - m[1][1] * m[2][0]) * s};
  const Vec3 e1{-(m[0][1] * m[2][2] - m[0][2] * m[2][1]) * s, (m[0][0] * m[2][2] - m[0][2] * m[2][0]) * s,
                -(m[0][0] * m[2][1] - m[0][1] * m[2][0]) * s};
  const Vec3 e2{(m[0][1] * m[1][2] - m[0][2] * m[1][1]) * s, -(m[0][0] * m[1][2] - m[0][2] * m[1][0]) * s,
                (m[0][0] * m[1][1] - m[0][1] * m[1][0]) * s};
  const double den = dot(ray.direction, e2);
  if (std::fabs(den) < kBezierEpsilon) return std::nullopt;
  const double t = dot(w0 - ray.origin, e2) / den;
  if (t < kBezierTolerance) return std::nullopt;
  const Vec3 q = (ray.origin + ray.direction * t) - w0;
  const double a = dot(q, e0), b = dot(q, e1);
  if (a < 0.0 || b < 0.0 || a + b > 1.0) return std::nullopt;
  return TriangleHit{t, a, b};
}

// The corners of triangle k (0: V0 V1 V2, 1: V0 V2 V3) of a leaf.
constexpr std::size_t kTriangleCorners[2][3] = {{0, 1, 2}, {0, 2, 3}};

// Walks the tree in POV-Ray's order (bezier_tree_walker), calling found(t, element, a, b) for each triangle hit.
template <class Found>
void walk(const BicubicPatchData& d, const Ray& ray, Found&& found) {
  std::uint32_t stack[64];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const BicubicPatchData::Node& node = d.nodes[stack[--top]];
    if (!passes_sphere(ray, node.centre, node.radius2)) continue;
    if (node.children > 0) {   // pushed last child first, so that they are visited in order
      for (int c = node.children - 1; c >= 0; --c) stack[top++] = node.first + static_cast<std::uint32_t>(c);
      continue;
    }
    const BicubicPatchData::Leaf& leaf = d.leaves[node.first];
    for (std::uint32_t k = 0; k < 2; ++k) {
      const auto& c = kTriangleCorners[k];
      if (const auto h = hit_triangle(ray, leaf.corner[c[0]], leaf.corner[c[1]], leaf.corner[c[2]]))
        found(h->t, 2 * node.first + k, h->a, h->b);
    }
  }
}

// The triangle's corners' parameters (u, v).
std::array<std::array<double, 2>, 3> corner_parameters(const BicubicPatchData::Leaf& leaf, std::uint32_t triangle) {
  if (triangle == 0) return {{{leaf.u0, leaf.v0}, {leaf.u0, leaf.v1}, {leaf.u1, leaf.v1}}};
  return {{{leaf.u0, leaf.v0}, {leaf.u1, leaf.v1}, {leaf.u1, leaf.v0}}};
}
}  // namespace

Primitive BicubicPatchShape::build(const BicubicPatch& description, const Matrix& world_from_object) {
  Primitive p = placed_primitive(ShapeType::bicubic_patch, Matrix{});   // the points are already in place
  p.data = bicubic_patch_data(description, world_from_object);
  return p;
}

void BicubicPatchShape::collect(const Primitive& p, const Ray& ray, HitBuffer& out) {
  walk(data_of(p), ray, [&](double t, std::uint32_t element, double a, double b) {
    out.push_back(SurfaceHit{t, &p, element, a, b});
  });
}

std::optional<SurfaceHit> BicubicPatchShape::nearest(const Primitive& p, const Ray& ray, double t_min, double t_max) {
  std::optional<SurfaceHit> best;
  walk(data_of(p), ray, [&](double t, std::uint32_t element, double a, double b) {
    // Of equal depths the last found wins: POV-Ray pops its stack of hits newest first and keeps a strictly nearer one.
    if (t > t_min && t < t_max && (!best || t <= best->t)) best = SurfaceHit{t, &p, element, a, b};
  });
  return best;
}

Vec3 BicubicPatchShape::hit_normal(const SurfaceHit& hit, Vec3) {
  const BicubicPatchData::Leaf& leaf = data_of(*hit.leaf).leaves[hit.element / 2];
  const auto& c = kTriangleCorners[hit.element % 2];
  const double a = hit.u, b = hit.v, r = 1.0 - a - b;
  Vec3 n;
  n += leaf.normal[c[0]] * r;
  n += leaf.normal[c[1]] * a;
  n += leaf.normal[c[2]] * b;
  const double n2 = dot(n, n);
  if (n2 > kBezierEpsilon) return n * (1.0 / std::sqrt(n2));
  return {1, 0, 0};
}

// Without a hit there is no triangle to blend over: the nearest leaf corner's normal (used by nothing that renders).
Vec3 BicubicPatchShape::normal(const Primitive& p, Vec3 world_point) {
  const BicubicPatchData& d = data_of(p);
  Vec3 best{1, 0, 0};
  double best_distance = std::numeric_limits<double>::infinity();
  for (const auto& leaf : d.leaves)
    for (std::size_t k = 0; k < 4; ++k)
      if (const double distance = dot(leaf.corner[k] - world_point, leaf.corner[k] - world_point);
          distance < best_distance) {
        best_distance = distance;
        best = leaf.normal[k];
      }
  return best;
}

// POV-Ray's Compute_Texture_UV at (v, u): the uv_vectors quad, first along v, then across u.
std::array<double, 2> BicubicPatchShape::uv(const SurfaceHit& hit, Vec3) {
  const BicubicPatchData& d = data_of(*hit.leaf);
  const BicubicPatchData::Leaf& leaf = d.leaves[hit.element / 2];
  const auto uv = corner_parameters(leaf, hit.element % 2);
  const double a = hit.u, b = hit.v, r = 1.0 - a - b;
  const double u = r * uv[0][0] + a * uv[1][0] + b * uv[2][0];
  const double v = r * uv[0][1] + a * uv[1][1] + b * uv[2][1];
  const auto& st = d.uv_vectors;
  const double low0 = st[0][0] + v * (st[1][0] - st[0][0]), low1 = st[0][1] + v * (st[1][1] - st[0][1]);
  const double high0 = st[3][0] + v * (st[2][0] - st[3][0]), high1 = st[3][1] + v * (st[2][1] - st[3][1]);
  return {low0 + u * (high0 - low0), low1 + u * (high1 - low1)};
}

Bounds BicubicPatchShape::world_bounds(const Primitive& p) { return data_of(p).bounds; }

}  // namespace povtrace::render::shapes
