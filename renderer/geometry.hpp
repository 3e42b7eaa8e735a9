// Render-ready geometry: rays, hits, world-space primitives with their own transforms, and the acceleration
// structure over them. Built once from the SceneDescription; immutable while rendering (STYLE.md (a) step 4).
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <type_traits>
#include <utility>
#include <vector>

#include "scene/vecmath.hpp"
#include "renderer/shapes/shape_list.hpp"

namespace povtrace::render {

// POV-Ray 3.7's numerical tolerances (povray-pixel-pipeline.md §8). Every tolerance of the renderer lives here.
namespace tolerance {
inline constexpr double min_isect_depth = 1e-4;     // MIN_ISECT_DEPTH: any ray ignores hits closer than this
inline constexpr double shadow = 1e-3;              // SHADOW_TOLERANCE / SMALL_TOLERANCE for shadow rays
inline constexpr double epsilon = 1e-10;            // "is zero" tests
inline constexpr double max_distance = 1e7;         // MAX_DISTANCE: sphere/plane roots beyond this are rejected
inline constexpr double bound_huge = 2e10;          // BOUND_HUGE: initial nearest-hit distance
inline constexpr double sphere_depth = 1e-6;        // DEPTH_TOLERANCE of sphere, plane, box
inline constexpr double plane_depth = 1e-6;
inline constexpr double box_depth = 1e-6;
}  // namespace tolerance

// What a ray is, for the object modifiers no_image and no_reflection (POV-Ray 3.7, source/backend/frame.h and
// render/ray.cpp): a ray carries a primary, a reflection and a refraction flag. A camera ray is primary; a
// reflected ray is reflection-flagged and keeps the refraction flag of the ray it came from, a refracted (or
// continued, ior 1) ray is refraction-flagged and keeps the reflection flag, so the two flags say whether a
// reflection or a refraction happened anywhere in the ray's history. An "image" ray is a primary ray or a
// refraction-flagged one without the reflection flag. Shadow rays carry no flag and see every object.
// Exactly one bit is set for a flagged ray (one per combination), so that what an object hides from is a mask.
// Scenes without these modifiers trace every ray as `other`, which no object hides from.
namespace ray_kind {
inline constexpr std::uint8_t other = 0;                    // shadow rays, and every ray of a scene without flags
inline constexpr std::uint8_t primary = 1;                  // camera rays
inline constexpr std::uint8_t reflected = 2;                // reflection flag only
inline constexpr std::uint8_t refracted = 4;                // refraction flag only (an image ray)
inline constexpr std::uint8_t reflected_refracted = 8;      // both flags
inline constexpr std::uint8_t image = primary | refracted;  // Ray::IsImageRay
inline constexpr std::uint8_t reflection = reflected | reflected_refracted;   // Ray::IsReflectionRay
// Added to the kinds above: a radiosity sample ray and every ray traced from it (Ray::IsRadiosityRay). A sample
// ray itself is POV-Ray's OtherRay with that flag: `radiosity` alone.
inline constexpr std::uint8_t radiosity = 16;

// The kind of a ray reflected (SetFlags(ReflectionRay, ray)) or refracted (SetFlags(RefractionRay, ray)) from a
// ray of kind k; `other` stays `other` (the scene has no flags).
constexpr std::uint8_t after_reflection(std::uint8_t k) {
  if (k == other) return other;
  return static_cast<std::uint8_t>(((k & (refracted | reflected_refracted)) ? reflected_refracted : reflected) |
                                   (k & radiosity));
}
constexpr std::uint8_t after_refraction(std::uint8_t k) {
  if (k == other) return other;
  return static_cast<std::uint8_t>(((k & reflection) ? reflected_refracted : refracted) | (k & radiosity));
}
}  // namespace ray_kind

// An object's no_image / no_reflection modifiers (Primitive::ray_flags).
namespace ray_flag {
inline constexpr std::uint8_t no_image = 1;
inline constexpr std::uint8_t no_reflection = 2;
inline constexpr std::uint8_t no_radiosity = 4;   // set only when the scene renders radiosity

// The ray kinds that skip an object with `flags`, as POV-Ray tests it: at the top level and for merge children
// (NoSomethingFlagRayObjectCondition, csg.cpp Test_Ray_Flags_Shadow) no_image hides from every image ray; for
// union children (Test_Ray_Flags) primary rays still see a no_image child, only refracted image rays skip it.
// Intersection children are never tested.
constexpr std::uint8_t hidden_from(std::uint8_t flags, bool union_child) {
  std::uint8_t kinds = 0;
  if (flags & no_image) kinds |= union_child ? ray_kind::refracted : ray_kind::image;
  if (flags & no_reflection) kinds |= ray_kind::reflection;
  if (flags & no_radiosity) kinds |= ray_kind::radiosity;   // union and merge children alike (Test_Ray_Flags*)
  return kinds;
}
}  // namespace ray_flag

struct Ray {
  Vec3 origin;
  Vec3 direction;  // unit length: every depth is a world distance
  std::uint8_t kind = ray_kind::other;   // for no_image / no_reflection (ray_kind above)
};

struct Bounds {
  Vec3 lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
          std::numeric_limits<double>::infinity()};
  Vec3 hi{-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
          -std::numeric_limits<double>::infinity()};
  void extend(Vec3 p) { lo = min(lo, p); hi = max(hi, p); }
  void extend(const Bounds& b) { lo = min(lo, b.lo); hi = max(hi, b.hi); }
  bool empty() const { return lo.x > hi.x; }
  bool finite() const;
  Vec3 centre() const { return (lo + hi) * 0.5; }
  double surface_area() const;
};

// One enumerator per registered shape, in the order of renderer/shapes/shape_list.hpp.
enum class ShapeType : std::uint8_t {
#define POVTRACE_SHAPE_ENUMERATOR(name, Shape) name,
  POVTRACE_SHAPES(POVTRACE_SHAPE_ENUMERATOR)
#undef POVTRACE_SHAPE_ENUMERATOR
};

// Shape parameters too large or too varied for Primitive's inline fields (CSG children, meshes, polygons): a shape
// derives its own data from this. Shared, not copied, between primitives (a declared mesh placed many times is
// stored once) and immutable once built.
struct ShapeData {
  virtual ~ShapeData() = default;
};

// One geometric primitive in its own object space plus the transform to world space.
struct Primitive {
  ShapeType type = ShapeType::sphere;
  // The object's own `radiosity { importance }` (a CSG child's as the parser resolved it), negative when it wrote
  // none: the scene's #default applies then. Read by radiosity sample rays at their first hit (the leaf hit, as
  // POV-Ray's Intersection::Object). Stored in the padding after `type`.
  float radiosity_importance = -1;
  // Object-space parameters: sphere a = centre, radius; plane a = unit normal N, radius = distance d (surface
  // N·P = d); box a = lo corner, b = hi corner; cylinder, cone, disc, torus: see renderer/shapes/quadric_shapes.hpp.
  Vec3 a, b;
  double radius = 0;
  bool transformed = false;      // false: world_from_object is the identity and is skipped
  Matrix world_from_object;
  Matrix object_from_world;
  std::uint32_t material = 0;    // index into the render scene's material table (owned by the shading side)
  std::uint32_t object = 0;      // index of the top-level scene object this primitive belongs to
  bool casts_shadow = true;      // false for no_shadow objects
  // The object's own no_image / no_reflection (ray_flag), which a CSG parent tests its children against, and the
  // ray kinds that skip this primitive as a top-level object (the BVH's test): ray_flag::hidden_from of its flags,
  // and for a union split into its children also what the union's own test and the children's tests add.
  std::uint8_t ray_flags = 0;
  std::uint8_t hidden_from = 0;
  bool inverse = false;          // inside/outside flipped
  bool double_illuminate = false;   // lit from both sides (the object's double_illuminate)
  // Part of a CSG node (a child, or a clipped or bounded shape): the node filters the hits, so a shape whose walk
  // otherwise ends at its first hit (a height field, as POV-Ray's block_traversal for IS_CHILD_OBJECT) reports
  // every one.
  bool csg_child = false;
  bool embree_nearest = false;   // a mesh whose nearest hits Embree finds (shapes/triangle_shapes.hpp)
  std::shared_ptr<const ShapeData> data;   // the shape's out-of-line parameters, if it has any
  std::uint32_t element_materials = 0;     // meshes: material of texture k of the mesh's list is this + k
};

// A primitive of `type` placed by `world_from_object` (marked transformed unless that is the identity), with the
// shape parameters and the material, object and flags still to set.
Primitive placed_primitive(ShapeType type, const Matrix& world_from_object);

// One intersection of a ray with a surface, with what shading needs to know about where it is.
struct SurfaceHit {
  double t = tolerance::bound_huge;   // world distance along the (unit) world ray
  const Primitive* leaf = nullptr;    // the primitive whose surface this is: the one tested, or the CSG child hit
  std::uint32_t element = 0;          // which part of the leaf (a mesh's triangle index)
  double u = 0, v = 0;                // where on that part (barycentric coordinates on a triangle)
};
// The material(s) at a hit: one (the leaf's, or a mesh triangle's own), or three with weights for a mesh triangle
// with a texture_list (POV-Ray shades with each texture and blends the colours by the barycentric weights).
struct MaterialBlend {
  static constexpr int kInline = 3;   // a mesh triangle's three; a blob's components past these go to `more`
  std::uint32_t material[kInline] = {0, 0, 0};
  double weight[kInline] = {1, 0, 0};
  int count = 1;
  std::vector<std::pair<std::uint32_t, double>> more;
  std::uint32_t material_of(int k) const { return k < kInline ? material[k] : more[std::size_t(k - kInline)].first; }
  double weight_of(int k) const { return k < kInline ? weight[k] : more[std::size_t(k - kInline)].second; }
  void set_weight(int k, double w) { (k < kInline ? weight[k] : more[std::size_t(k - kInline)].second) = w; }
  void add(std::uint32_t m, double w) {
    if (count < kInline) {
      material[count] = m;
      weight[count] = w;
    } else {
      more.emplace_back(m, w);
    }
    ++count;
  }
};
// `world_point`: where on the leaf (a blob with component textures weighs them there).
MaterialBlend materials_at(const SurfaceHit& hit, Vec3 world_point);

// The uv coordinates of a hit for uv_mapping (POV-Ray's UVCoord, shapes/uv_coordinates.cpp): spheres, boxes, tori
// and meshes have their own; every other shape gives the world point's x and y, divided by `scene_scale` (the factor a
// rescaled twin of the scene was made with, renderer/scene_scale.hpp), so that they are the scene's own.
std::array<double, 2> uv_coordinates(const SurfaceHit& hit, Vec3 world_point, double scene_scale = 1.0);

// Scratch list of hits. Shapes with many roots (CSG, meshes) append to one, so that a ray allocates only while a
// thread's buffer is still growing.
using HitBuffer = std::vector<SurfaceHit>;

// Nearest surface found along a ray: the top-level primitive (index into Accelerator::primitives()) and the surface
// hit inside it.
struct Hit {
  double t = tolerance::bound_huge;
  std::uint32_t primitive = ~0u;
  SurfaceHit surface;
  bool found() const { return primitive != ~0u; }
};

// Every intersection of a ray with a primitive whose surface has few roots (the quadric-like shapes: depth-sorted,
// at most 4). Depths are world distances along the (unit) world ray; only roots with depth > the shape's
// DEPTH_TOLERANCE and < max_distance (where POV-Ray applies it) are returned. Shapes with data (CSG, meshes) have
// no fixed bound on their roots and answer through collect_hits only.
struct Intersections {
  static constexpr int capacity = 4;
  double t[capacity];
  std::uint32_t element[capacity] = {};   // which part of the surface each root is on (a box's face), else 0
  int count = 0;
};
Intersections intersect_all(const Primitive& p, const Ray& ray);

// Appends every intersection of p with the ray (same depth rules as intersect_all, any order) to `out`. Works for
// every shape.
void collect_hits(const Primitive& p, const Ray& ray, HitBuffer& out);

// The nearest intersection of p with depth in (t_min, t_max), if there is one. Works for every shape.
std::optional<SurfaceHit> nearest_hit(const Primitive& p, const Ray& ray, double t_min, double t_max);

// The world point of a hit: where the ray is at its depth, or for a julia_fractal the point its march found (POV-Ray's
// IPoint, which the depth does not give back to the last bit).
Vec3 hit_point(const Ray& ray, const SurfaceHit& hit);

// World-space unit normal at a world-space point on the primitive (not flipped toward the ray; `inverse` does
// not change it either — the shading side flips normals to face the viewer as POV-Ray does).
Vec3 surface_normal(const Primitive& p, Vec3 world_point);
// The same at a hit, for every shape (the leaf primitive, and for meshes the triangle and its coordinates).
Vec3 surface_normal(const SurfaceHit& hit, Vec3 world_point);

// POV-Ray's inside test for the primitive at a world point (pipeline docs §8 table), honouring `inverse`.
bool inside(const Primitive& p, Vec3 world_point);

// World-space bounds; infinite (non-finite) for planes.
Bounds world_bounds(const Primitive& p);

// The acceleration structure: a binned-SAH BVH over the bounded primitives, with unbounded ones (planes) kept in
// a separate list tested for every ray. Build is O(n log n); traversal allocates nothing.
class Accelerator {
 public:
  Accelerator() = default;
  explicit Accelerator(std::vector<Primitive> primitives);

  std::span<const Primitive> primitives() const { return primitives_; }

  // Nearest hit with t in (t_min, t_max): t_min = MIN_ISECT_DEPTH for ordinary rays.
  Hit closest_hit(const Ray& ray, double t_min, double t_max) const;

  // Nearest hit with t in (t_min, t_max) among the shadow-casting primitives: the first crossing of the shadow
  // walk (for_each_shadow_hit's hits, sorted), found without collecting the others.
  Hit closest_shadow_hit(const Ray& ray, double t_min, double t_max) const;

  // Calls visit(primitive_index, surface_hit) for every intersection with t in (t_min, t_max) of a shadow-casting
  // primitive, in no particular order; visit returns false to stop early. Used by shadow rays (opaque objects
  // stop at the first hit; transparent ones are filtered at every crossing).
  template <class Visit>
  void for_each_shadow_hit(const Ray& ray, double t_min, double t_max, Visit&& visit) const;

  // Calls visit(primitive_index) for every primitive whose inside test holds at `point` (POV-Ray's containing
  // objects of a ray origin), in primitive order.
  template <class Visit>
  void for_each_containing(Vec3 point, Visit&& visit) const {
    for (const std::uint32_t i : containing_indices(point)) visit(i);
  }

  // Brute-force reference used by tests (same contract as closest_hit).
  Hit closest_hit_brute_force(const Ray& ray, double t_min, double t_max) const;

 private:
  struct Node {
    Bounds bounds;
    std::uint32_t first = 0;   // leaf: first index into order_; inner: index of the right child
    std::uint16_t count = 0;   // leaf: number of primitives; 0 for inner nodes
    std::uint16_t axis = 0;    // inner: split axis (front-to-back traversal order)
  };
  std::vector<Primitive> primitives_;
  std::vector<std::uint32_t> order_;      // bounded primitives in leaf order
  std::vector<std::uint32_t> unbounded_;  // planes and anything with non-finite bounds
  std::vector<Node> nodes_;               // nodes_[0] is the root; left child of node i is i + 1
  // Build and traversal live in renderer/accel/bvh.cpp. for_each_shadow_hit forwards to this non-template walk
  // through a plain function pointer plus context (no allocation, one indirect call per reported root).
  std::vector<std::uint32_t> containing_indices(Vec3 point) const;
  template <bool shadow_casters_only>
  Hit nearest(const Ray& ray, double t_min, double t_max) const;
  using ShadowVisitFn = bool (*)(void* context, std::uint32_t primitive, const SurfaceHit& hit);
  void shadow_traverse(const Ray& ray, double t_min, double t_max, ShadowVisitFn visit, void* context) const;
  std::uint32_t build_node(std::uint32_t begin, std::uint32_t end, int depth, const std::vector<Bounds>& bounds,
                           const std::vector<Vec3>& centroids);
  friend class AcceleratorTestAccess;
};

template <class Visit>
void Accelerator::for_each_shadow_hit(const Ray& ray, double t_min, double t_max, Visit&& visit) const {
  using V = std::remove_reference_t<Visit>;
  ShadowVisitFn thunk = [](void* context, std::uint32_t primitive, const SurfaceHit& hit) -> bool {
    V& v = *static_cast<V*>(context);
    if constexpr (std::is_void_v<std::invoke_result_t<V&, std::uint32_t, const SurfaceHit&>>) {
      v(primitive, hit);
      return true;
    } else {
      return static_cast<bool>(v(primitive, hit));
    }
  };
  shadow_traverse(ray, t_min, t_max, thunk, const_cast<void*>(static_cast<const void*>(std::addressof(visit))));
}

}  // namespace povtrace::render
