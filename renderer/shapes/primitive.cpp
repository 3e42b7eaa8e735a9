// Primitive dispatch: intersect_all / surface_normal / inside / world_bounds switch on ShapeType and forward to the
// per-shape functions in each shape's own file (sphere.cpp … blob.cpp, lathe.cpp, prism.cpp, sor.cpp). Each shape applies its own transform because POV-Ray
// applies the depth tolerances in different spaces per shape (see the header comment of each shape file).
// Also the two non-inline Bounds members.
#include <array>
#include <cmath>

#include "renderer/geometry.hpp"
#include "renderer/shapes/triangle_shapes.hpp"
#include "renderer/shapes/many_roots.hpp"

namespace povtrace::render {

namespace shapes {
// Per-shape entry points (defined in the shape's own .cpp; there is deliberately no header for them, the public
// interface is geometry.hpp). All take world-space rays/points; object-space bounds are carried to world here.
Intersections intersect_sphere(const Primitive& p, const Ray& ray);
Vec3 sphere_normal(const Primitive& p, Vec3 world_point);
bool inside_sphere(const Primitive& p, Vec3 world_point);
Bounds sphere_object_bounds(const Primitive& p);

Intersections intersect_plane(const Primitive& p, const Ray& ray);
Vec3 plane_normal(const Primitive& p, Vec3 world_point);
bool inside_plane(const Primitive& p, Vec3 world_point);
Bounds plane_world_bounds(const Primitive& p);

Intersections intersect_box(const Primitive& p, const Ray& ray);
Vec3 box_normal(const Primitive& p, Vec3 world_point);
Vec3 box_face_normal(const Primitive& p, std::uint32_t side);
bool inside_box(const Primitive& p, Vec3 world_point);
Bounds box_object_bounds(const Primitive& p);

Intersections intersect_cylinder(const Primitive& p, const Ray& ray);
Vec3 cylinder_normal(const Primitive& p, Vec3 world_point);
bool inside_cylinder(const Primitive& p, Vec3 world_point);
Bounds cylinder_object_bounds(const Primitive& p);

Intersections intersect_cone(const Primitive& p, const Ray& ray);
Vec3 cone_normal(const Primitive& p, Vec3 world_point);
bool inside_cone(const Primitive& p, Vec3 world_point);
Bounds cone_object_bounds(const Primitive& p);

Intersections intersect_disc(const Primitive& p, const Ray& ray);
Vec3 disc_normal(const Primitive& p, Vec3 world_point);
bool inside_disc(const Primitive& p, Vec3 world_point);
Bounds disc_object_bounds(const Primitive& p);

Intersections intersect_torus(const Primitive& p, const Ray& ray);
Vec3 torus_normal(const Primitive& p, Vec3 world_point);
bool inside_torus(const Primitive& p, Vec3 world_point);
Bounds torus_object_bounds(const Primitive& p);

Intersections intersect_poly(const Primitive& p, const Ray& ray);
Vec3 poly_normal(const Primitive& p, Vec3 world_point);
bool inside_poly(const Primitive& p, Vec3 world_point);
Bounds poly_world_bounds(const Primitive& p);

Intersections intersect_quadric(const Primitive& p, const Ray& ray);
Vec3 quadric_normal(const Primitive& p, Vec3 world_point);
bool inside_quadric(const Primitive& p, Vec3 world_point);
Bounds quadric_world_bounds(const Primitive& p);
Vec3 superellipsoid_normal(const Primitive& p, Vec3 world_point);
bool inside_superellipsoid(const Primitive& p, Vec3 world_point);
Bounds superellipsoid_object_bounds(const Primitive& p);

Vec3 height_field_normal(const Primitive& p, Vec3 world_point);
Vec3 height_field_hit_normal(const Primitive& p, std::uint32_t element, Vec3 world_point);
bool inside_height_field(const Primitive& p, Vec3 world_point);
Bounds height_field_object_bounds(const Primitive& p);

Vec3 blob_normal(const Primitive& p, Vec3 world_point);
bool inside_blob(const Primitive& p, Vec3 world_point);
Bounds blob_object_bounds(const Primitive& p);
// CSG nodes (csg.cpp): hits come from the children through collect_hits, so there is no intersect_all.
void collect_csg_hits(const Primitive& p, const Ray& ray, HitBuffer& out);
bool nearest_csg_hit(const Primitive& p, const Ray& ray, double t_min, double t_max, SurfaceHit& hit);
Vec3 csg_normal(const Primitive& p, Vec3 world_point);
bool inside_csg(const Primitive& p, Vec3 world_point);
Bounds csg_world_bounds(const Primitive& p);
// Text (text.cpp): any number of roots, and a normal that comes with the hit.
void collect_text_hits(const Primitive& p, const Ray& ray, HitBuffer& out);
bool nearest_text_hit(const Primitive& p, const Ray& ray, double t_min, double t_max, SurfaceHit& hit);
Vec3 text_hit_normal(const SurfaceHit& hit);
Vec3 text_normal(const Primitive& p, Vec3 world_point);
bool inside_text(const Primitive& p, Vec3 world_point);
Bounds text_object_bounds(const Primitive& p);

// lathe, prism, sor: the normal depends on the segment hit (element) and, for lathe and prism, where on it (w).
Vec3 lathe_normal(const Primitive& p, Vec3 world_point);
Vec3 lathe_hit_normal(const Primitive& p, std::uint32_t segment, double w, Vec3 world_point);
bool inside_lathe(const Primitive& p, Vec3 world_point);
Bounds lathe_object_bounds(const Primitive& p);

Vec3 prism_normal(const Primitive& p, Vec3 world_point);
Vec3 prism_hit_normal(const Primitive& p, std::uint32_t element, double w, Vec3 world_point);
bool inside_prism(const Primitive& p, Vec3 world_point);
Bounds prism_object_bounds(const Primitive& p);

Vec3 sor_normal(const Primitive& p, Vec3 world_point);
Vec3 sor_hit_normal(const Primitive& p, std::uint32_t element, Vec3 world_point);
bool inside_sor(const Primitive& p, Vec3 world_point);
Bounds sor_object_bounds(const Primitive& p);

Vec3 isosurface_normal(const Primitive& p, Vec3 world_point);
Vec3 isosurface_hit_normal(const Primitive& p, std::uint32_t side, Vec3 world_point);
bool inside_isosurface(const Primitive& p, Vec3 world_point);
Bounds isosurface_object_bounds(const Primitive& p);
}  // namespace shapes

bool Bounds::finite() const {
  for (int i = 0; i < 3; ++i)
    if (!std::isfinite(lo[i]) || !std::isfinite(hi[i])) return false;
  return !empty();
}

double Bounds::surface_area() const {
  if (empty()) return 0.0;
  const Vec3 e = hi - lo;
  return 2.0 * (e.x * e.y + e.y * e.z + e.z * e.x);
}

Intersections intersect_all(const Primitive& p, const Ray& ray) {
  switch (p.type) {
    case ShapeType::sphere: return shapes::intersect_sphere(p, ray);
    case ShapeType::plane: return shapes::intersect_plane(p, ray);
    case ShapeType::box: return shapes::intersect_box(p, ray);
    case ShapeType::cylinder: return shapes::intersect_cylinder(p, ray);
    case ShapeType::cone: return shapes::intersect_cone(p, ray);
    case ShapeType::disc: return shapes::intersect_disc(p, ray);
    case ShapeType::torus: return shapes::intersect_torus(p, ray);
    case ShapeType::poly: return shapes::intersect_poly(p, ray);
    case ShapeType::quadric: return shapes::intersect_quadric(p, ray);
    case ShapeType::triangle: return shapes::intersect_triangle(p, ray);
    case ShapeType::polygon: return shapes::intersect_polygon(p, ray);
    case ShapeType::mesh: return {};   // any number of roots: collect_hits and nearest_hit only
    case ShapeType::csg: return {};
    case ShapeType::text: return {};   // any number of roots: collect_hits and nearest_hit only
    case ShapeType::superellipsoid:
    case ShapeType::height_field:
    case ShapeType::blob:
    case ShapeType::lathe:
    case ShapeType::prism:
    case ShapeType::sor:
    case ShapeType::isosurface: return shapes::first_roots(p, ray);
  }
  return {};
}

void collect_hits(const Primitive& p, const Ray& ray, HitBuffer& out) {
  if (p.type == ShapeType::mesh) return shapes::collect_mesh_hits(p, ray, out);
  if (shapes::has_many_roots(p.type)) return shapes::collect_many_roots(p, ray, out);
  if (p.type == ShapeType::csg) return shapes::collect_csg_hits(p, ray, out);
  if (p.type == ShapeType::text) return shapes::collect_text_hits(p, ray, out);
  const Intersections xs = intersect_all(p, ray);
  for (int k = 0; k < xs.count; ++k) out.push_back(SurfaceHit{xs.t[k], &p, xs.element[k], 0, 0});
}

bool nearest_hit(const Primitive& p, const Ray& ray, double t_min, double t_max, SurfaceHit& hit) {
  if (p.type == ShapeType::mesh) return shapes::nearest_mesh_hit(p, ray, t_min, t_max, hit);
  if (shapes::has_many_roots(p.type)) return shapes::nearest_of_many_roots(p, ray, t_min, t_max, hit);
  if (p.type == ShapeType::csg) return shapes::nearest_csg_hit(p, ray, t_min, t_max, hit);
  if (p.type == ShapeType::text) return shapes::nearest_text_hit(p, ray, t_min, t_max, hit);
  const Intersections xs = intersect_all(p, ray);
  for (int k = 0; k < xs.count; ++k) {
    if (!(xs.t[k] > t_min)) continue;
    if (!(xs.t[k] < t_max)) return false;   // roots are depth-sorted: the first one above t_min decides
    hit = SurfaceHit{xs.t[k], &p, xs.element[k], 0, 0};
    return true;
  }
  return false;
}

Vec3 surface_normal(const SurfaceHit& hit, Vec3 world_point) {
  if (hit.leaf->type == ShapeType::mesh) return shapes::mesh_hit_normal(hit);
  if (hit.leaf->type == ShapeType::text) return shapes::text_hit_normal(hit);
  // A height field's flat triangles: the one hit decides (POV-Ray keeps its normal with the intersection).
  if (hit.leaf->type == ShapeType::height_field) return shapes::height_field_hit_normal(*hit.leaf, hit.element, world_point);
  // Lathes, prisms and sors: the segment (or end disc) hit and the segment parameter there (kept in u).
  if (hit.leaf->type == ShapeType::lathe) return shapes::lathe_hit_normal(*hit.leaf, hit.element, hit.u, world_point);
  if (hit.leaf->type == ShapeType::prism) return shapes::prism_hit_normal(*hit.leaf, hit.element, hit.u, world_point);
  if (hit.leaf->type == ShapeType::sor) return shapes::sor_hit_normal(*hit.leaf, hit.element, world_point);
  if (hit.leaf->type == ShapeType::isosurface) return shapes::isosurface_hit_normal(*hit.leaf, hit.element, world_point);
  // A box: the face the slab test entered or left by (POV-Ray's Side1/Side2).
  if (hit.leaf->type == ShapeType::box) return shapes::box_face_normal(*hit.leaf, hit.element);
  return surface_normal(*hit.leaf, world_point);
}

Vec3 surface_normal(const Primitive& p, Vec3 world_point) {
  switch (p.type) {
    case ShapeType::sphere: return shapes::sphere_normal(p, world_point);
    case ShapeType::plane: return shapes::plane_normal(p, world_point);
    case ShapeType::box: return shapes::box_normal(p, world_point);
    case ShapeType::cylinder: return shapes::cylinder_normal(p, world_point);
    case ShapeType::cone: return shapes::cone_normal(p, world_point);
    case ShapeType::disc: return shapes::disc_normal(p, world_point);
    case ShapeType::torus: return shapes::torus_normal(p, world_point);
    case ShapeType::poly: return shapes::poly_normal(p, world_point);
    case ShapeType::quadric: return shapes::quadric_normal(p, world_point);
    case ShapeType::triangle: return shapes::triangle_normal(p, world_point);
    case ShapeType::polygon: return shapes::polygon_normal(p, world_point);
    case ShapeType::mesh: return shapes::mesh_normal(p, world_point);
    case ShapeType::superellipsoid: return shapes::superellipsoid_normal(p, world_point);
    case ShapeType::height_field: return shapes::height_field_normal(p, world_point);
    case ShapeType::blob: return shapes::blob_normal(p, world_point);
    case ShapeType::csg: return shapes::csg_normal(p, world_point);
    case ShapeType::text: return shapes::text_normal(p, world_point);
    case ShapeType::lathe: return shapes::lathe_normal(p, world_point);
    case ShapeType::prism: return shapes::prism_normal(p, world_point);
    case ShapeType::sor: return shapes::sor_normal(p, world_point);
    case ShapeType::isosurface: return shapes::isosurface_normal(p, world_point);
  }
  return {};
}

bool inside(const Primitive& p, Vec3 world_point) {
  switch (p.type) {
    case ShapeType::sphere: return shapes::inside_sphere(p, world_point);
    case ShapeType::plane: return shapes::inside_plane(p, world_point);
    case ShapeType::box: return shapes::inside_box(p, world_point);
    case ShapeType::cylinder: return shapes::inside_cylinder(p, world_point);
    case ShapeType::cone: return shapes::inside_cone(p, world_point);
    case ShapeType::disc: return shapes::inside_disc(p, world_point);
    case ShapeType::torus: return shapes::inside_torus(p, world_point);
    case ShapeType::poly: return shapes::inside_poly(p, world_point);
    case ShapeType::quadric: return shapes::inside_quadric(p, world_point);
    case ShapeType::triangle: return false;   // POV-Ray: never inside, inverse or not
    case ShapeType::polygon: return false;
    case ShapeType::mesh: return shapes::inside_mesh(p, world_point);
    case ShapeType::superellipsoid: return shapes::inside_superellipsoid(p, world_point);
    case ShapeType::height_field: return shapes::inside_height_field(p, world_point);
    case ShapeType::blob: return shapes::inside_blob(p, world_point);
    case ShapeType::csg: return shapes::inside_csg(p, world_point);
    case ShapeType::text: return shapes::inside_text(p, world_point);
    case ShapeType::lathe: return shapes::inside_lathe(p, world_point);
    case ShapeType::prism: return shapes::inside_prism(p, world_point);
    case ShapeType::sor: return shapes::inside_sor(p, world_point);
    case ShapeType::isosurface: return shapes::inside_isosurface(p, world_point);
  }
  return false;
}

namespace {
// World bounds of an object-space box: the box of its 8 transformed corners.
Bounds to_world(const Primitive& p, const Bounds& object) {
  if (!p.transformed || object.empty()) return object;
  Bounds world;
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3 c{(corner & 1) ? object.hi.x : object.lo.x, (corner & 2) ? object.hi.y : object.lo.y,
                 (corner & 4) ? object.hi.z : object.lo.z};
    world.extend(p.world_from_object.point(c));
  }
  return world;
}
}  // namespace

Bounds world_bounds(const Primitive& p) {
  switch (p.type) {
    case ShapeType::sphere: return to_world(p, shapes::sphere_object_bounds(p));
    case ShapeType::plane: return shapes::plane_world_bounds(p);
    case ShapeType::box: return to_world(p, shapes::box_object_bounds(p));
    case ShapeType::cylinder: return to_world(p, shapes::cylinder_object_bounds(p));
    case ShapeType::cone: return to_world(p, shapes::cone_object_bounds(p));
    case ShapeType::disc: return to_world(p, shapes::disc_object_bounds(p));
    case ShapeType::torus: return to_world(p, shapes::torus_object_bounds(p));
    case ShapeType::poly: return shapes::poly_world_bounds(p);
    case ShapeType::quadric: return shapes::quadric_world_bounds(p);
    case ShapeType::triangle: return shapes::triangle_world_bounds(p);
    case ShapeType::polygon: return to_world(p, shapes::polygon_object_bounds(p));
    case ShapeType::mesh: return to_world(p, shapes::mesh_object_bounds(p));
    case ShapeType::superellipsoid: return to_world(p, shapes::superellipsoid_object_bounds(p));
    case ShapeType::height_field: return to_world(p, shapes::height_field_object_bounds(p));
    case ShapeType::blob: return to_world(p, shapes::blob_object_bounds(p));
    case ShapeType::csg: return shapes::csg_world_bounds(p);
    case ShapeType::text: return to_world(p, shapes::text_object_bounds(p));
    case ShapeType::lathe: return to_world(p, shapes::lathe_object_bounds(p));
    case ShapeType::prism: return to_world(p, shapes::prism_object_bounds(p));
    case ShapeType::sor: return to_world(p, shapes::sor_object_bounds(p));
    case ShapeType::isosurface: return to_world(p, shapes::isosurface_object_bounds(p));
  }
  return {};
}

}  // namespace povtrace::render
