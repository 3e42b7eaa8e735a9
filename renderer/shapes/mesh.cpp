// Mesh and mesh2.
//
// SDL: `mesh { triangle {…} smooth_triangle {…} … [inside_vector V] }`, and
// `mesh2 { vertex_vectors … face_indices … }` (POV-Ray 3.7 reference "Mesh", "Mesh2"); the parser
// (parser/objects/meshes.cpp, mesh2.cpp) reduces both to the same flat arrays.
//
// POV-Ray behaviour reproduced (facts read from source/backend/shape/mesh.cpp, 3.7-stable):
// - The world ray is carried into the mesh's object space and normalised (length L); a triangle's object-space
//   depth must satisfy DEPTH_TOLERANCE (1e-6) ≤ depth ≤ MAX_DISTANCE (1e7); the reported world depth is depth / L.
// - Normal: a flat triangle's face normal; a smooth one's vertex normals interpolated across the triangle
//   (barycentric), both carried to world space by the inverse transpose and normalised.
// - Inside (only with inside_vector): the parity of the triangles crossed by a ray from the point along
//   inside_vector taken as a world direction (carried into object space and normalised), at depths in
//   [1e-6, 1e7]; `inverse` flips it. Without inside_vector nothing is inside, inverse or not.
// - Textures (Mesh::Determine_Textures): a triangle's own texture, else the mesh's; a texture_list triangle
//   blends its three textures' shaded colours with the barycentric weights of its vertices.
// - Where POV-Ray tests edges in the dominant plane, povtrace uses the watertight test (watertight.hpp): rays
//   through shared edges and vertices of a closed mesh never pass between its triangles.
// The triangles sit in a per-mesh BVH (renderer/accel/triangle_bvh.hpp), built once per mesh and shared by every
// placement of it: the scene's Accelerator holds one primitive per placement, a two-level hierarchy.
#include <algorithm>
#include <cmath>
#include <limits>

#include "renderer/shapes/triangle_shapes.hpp"
#include "renderer/shapes/watertight.hpp"
#include "renderer/shapes/mesh.hpp"
#include "renderer/shapes/blob.hpp"
#include "renderer/shared_meshes.hpp"

namespace povtrace::render::shapes {

namespace {
constexpr double depth_tolerance = 1e-6;

const MeshShapeData& shape_of(const Primitive& p) { return static_cast<const MeshShapeData&>(*p.data); }

// The world ray in object space, normalised, with the factor L that turns object depths into world depths.
struct ObjectRay {
  Ray ray;
  double length = 1.0;
};
ObjectRay to_object(const Primitive& p, const Ray& ray) {
  if (!p.transformed) return {ray, 1.0};
  const Vec3 d = p.object_from_world.vector(ray.direction);
  const double len = length(d);
  return {Ray{p.object_from_world.point(ray.origin), d * (1.0 / len)}, len};
}

// Calls found(triangle, object_depth, hit) for every triangle the object ray crosses at an object depth in
// [1e-6, 1e7] and a world depth in (t_min, t_max); found may lower t_max (world) and returns false to stop.
template <class Found>
void walk_triangles(const MeshShapeData& mesh, const ObjectRay& r, double t_min, double& t_max, Found&& found) {
  const MeshData& data = *mesh.data;
  const ShearedRay sheared(r.ray);
  const double object_min = std::max(depth_tolerance, t_min * r.length) * (1.0 - 1e-12);
  double object_max = std::min(tolerance::max_distance, t_max * r.length) * (1.0 + 1e-12);
  mesh.bvh.traverse(r.ray, object_min, object_max, [&](std::uint32_t tri) {
    const std::uint32_t* f = &data.faces[3 * std::size_t(tri)];
    TriangleHit hit;
    if (!intersect_watertight(sheared, data.vertex(f[0]), data.vertex(f[1]), data.vertex(f[2]), hit)) return true;
    if (hit.t < depth_tolerance || hit.t > tolerance::max_distance) return true;
    const double world = hit.t / r.length;
    if (!(world > t_min && world < t_max)) return true;
    const bool go_on = found(tri, world, hit);
    object_max = std::min(tolerance::max_distance, t_max * r.length) * (1.0 + 1e-12);
    return go_on;
  });
}

Vec3 object_normal(const MeshData& data, std::uint32_t tri, double u, double v) {
  const std::uint32_t* f = &data.faces[3 * std::size_t(tri)];
  if (!data.face_normals.empty() && data.face_normals[3 * std::size_t(tri)] != MeshData::flat) {
    const std::uint32_t* n = &data.face_normals[3 * std::size_t(tri)];
    return data.normal(n[0]) * (1.0 - u - v) + data.normal(n[1]) * u + data.normal(n[2]) * v;
  }
  const Vec3 a = data.vertex(f[0]), b = data.vertex(f[1]), c = data.vertex(f[2]);
  return cross(c - a, b - a);
}

Vec3 to_world_normal(const Primitive& p, Vec3 n) {
  if (p.transformed) n = p.object_from_world.normal_from_inverse(n);
  return normalize(n);
}
}  // namespace

std::shared_ptr<const MeshShapeData> make_mesh_shape(const std::shared_ptr<const MeshData>& data) {
  auto shape = std::make_shared<MeshShapeData>();
  shape->data = data;
  shape->bvh = TriangleBvh(data->vertices, data->faces);
  return shape;
}

void set_up_mesh(Primitive& p, std::shared_ptr<const MeshShapeData> shape) { p.data = std::move(shape); }

void prepare_embree_mesh(Primitive& p) {
  const MeshShapeData& mesh = shape_of(p);
  std::call_once(mesh.embree_once, [&] { mesh.embree = EmbreeMesh::build(mesh.data->vertices, mesh.data->faces); });
  p.embree_nearest = mesh.embree != nullptr;
}

void MeshShape::collect(const Primitive& p, const Ray& ray, HitBuffer& out) {
  double t_max = tolerance::bound_huge;
  walk_triangles(shape_of(p), to_object(p, ray), 0.0, t_max, [&](std::uint32_t tri, double t, const TriangleHit& h) {
    out.push_back(SurfaceHit{t, &p, tri, h.u, h.v});
    return true;
  });
}

// Embree picks the nearest triangle; its depth and weights are the watertight test's, under the same limits as
// walk_triangles. Not `decided` when that test disagrees with Embree's pick (the own walk then answers).
struct EmbreeAnswer {
  bool decided = true;
  std::optional<SurfaceHit> hit;
};

EmbreeAnswer embree_nearest_hit(const Primitive& p, const MeshShapeData& mesh, const Ray& ray, double t_min,
                                double t_max) {
  const ObjectRay r = to_object(p, ray);
  const double object_min = std::max(depth_tolerance, t_min * r.length);
  const double object_max = std::min(tolerance::max_distance, t_max * r.length);
  std::uint32_t tri = 0;
  if (!mesh.embree->nearest(r.ray, object_min, object_max, tri)) return {};
  const MeshData& data = *mesh.data;
  const std::uint32_t* f = &data.faces[3 * std::size_t(tri)];
  TriangleHit h;
  const bool crossed = intersect_watertight(ShearedRay(r.ray), data.vertex(f[0]), data.vertex(f[1]),
                                            data.vertex(f[2]), h);
  const double world = h.t / r.length;
  if (!crossed || h.t < depth_tolerance || h.t > tolerance::max_distance || !(world > t_min && world < t_max))
    return {false, std::nullopt};
  return {true, SurfaceHit{world, &p, tri, h.u, h.v}};
}

std::optional<SurfaceHit> MeshShape::nearest(const Primitive& p, const Ray& ray, double t_min, double t_max) {
  if (p.embree_nearest) {
    EmbreeAnswer answer = embree_nearest_hit(p, shape_of(p), ray, t_min, t_max);
    if (answer.decided) return answer.hit;
  }
  std::optional<SurfaceHit> nearest;
  walk_triangles(shape_of(p), to_object(p, ray), t_min, t_max, [&](std::uint32_t tri, double t, const TriangleHit& h) {
    nearest = SurfaceHit{t, &p, tri, h.u, h.v};
    t_max = t;
    return true;
  });
  return nearest;
}

Vec3 MeshShape::hit_normal(const SurfaceHit& hit, Vec3) {
  return to_world_normal(*hit.leaf, object_normal(*shape_of(*hit.leaf).data, hit.element, hit.u, hit.v));
}

// Without a hit: the normal of the triangle whose plane passes nearest the point among those containing its
// projection (a linear search; the tracer always has the hit).
Vec3 MeshShape::normal(const Primitive& p, Vec3 world_point) {
  const MeshData& data = *shape_of(p).data;
  const Vec3 q = p.transformed ? p.object_from_world.point(world_point) : world_point;
  double best = std::numeric_limits<double>::infinity();
  Vec3 normal{0, 1, 0};
  for (std::uint32_t tri = 0; tri < data.triangle_count(); ++tri) {
    const std::uint32_t* f = &data.faces[3 * std::size_t(tri)];
    const Vec3 a = data.vertex(f[0]), b = data.vertex(f[1]), c = data.vertex(f[2]);
    const Vec3 n = cross(b - a, c - a);
    const double n2 = dot(n, n);
    const double u = dot(n, cross(q - a, c - a)) / n2, v = dot(n, cross(b - a, q - a)) / n2;
    const double distance = std::fabs(dot(q - a, n)) / std::sqrt(n2);
    if (u < -1e-9 || v < -1e-9 || u + v > 1 + 1e-9 || distance >= best) continue;
    best = distance;
    normal = object_normal(data, tri, u, v);
  }
  return to_world_normal(p, normal);
}

bool MeshShape::inside(const Primitive& p, Vec3 world_point) {
  const MeshShapeData& mesh = shape_of(p);
  if (!mesh.data->inside_vector) return false;
  std::size_t crossings = 0;
  double t_max = tolerance::bound_huge;
  walk_triangles(mesh, to_object(p, Ray{world_point, *mesh.data->inside_vector}), 0.0, t_max,
                 [&](std::uint32_t, double, const TriangleHit&) {
                   ++crossings;
                   return true;
                 });
  return (crossings % 2 == 1) != p.inverse;
}

Bounds MeshShape::object_bounds(const Primitive& p) { return shape_of(p).bvh.bounds(); }

Primitive MeshShape::build(const Mesh& mesh, const Matrix& world_from_object, const BuildContext& context) {
  Primitive p = placed_primitive(ShapeType::mesh, world_from_object);
  set_up_mesh(p, context.meshes.shape_for(mesh.data));
  return p;
}

// uv for uv_mapping as POV-Ray's Mesh::UVCoord (mesh.cpp): the triangle's uv_vectors weighted by the point's
// barycentric coordinates (<0, 0> without uv_vectors).
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

namespace povtrace::render {

// A hit's material(s): the leaf's, or for a mesh triangle with textures of its own, the materials of those
// (texture k of the placement's list is material element_materials + k).
MaterialBlend materials_at(const SurfaceHit& hit, Vec3 world_point) {
  const Primitive& p = *hit.leaf;
  MaterialBlend blend;
  blend.material[0] = p.material;
  if (p.type == ShapeType::blob && shapes::blob_texture_count(p) > 0) {
    shapes::blob_materials(p, world_point, blend);
    return blend;
  }
  if (p.type != ShapeType::mesh) return blend;
  const MeshData& data = *shapes::shape_of(p).data;
  if (data.face_textures.empty()) return blend;
  const std::int32_t* t = &data.face_textures[3 * std::size_t(hit.element)];
  if (t[0] < 0) return blend;
  blend.material[0] = p.element_materials + static_cast<std::uint32_t>(t[0]);
  if (t[1] < 0) return blend;
  blend.count = 3;
  blend.material[1] = p.element_materials + static_cast<std::uint32_t>(t[1]);
  blend.material[2] = p.element_materials + static_cast<std::uint32_t>(t[2]);
  blend.weight[0] = 1.0 - hit.u - hit.v;
  blend.weight[1] = hit.u;
  blend.weight[2] = hit.v;
  return blend;
}

}  // namespace povtrace::render
