#include "renderer/object_geometry.hpp"

#include <filesystem>
#include <vector>

#include "renderer/csg_build.hpp"
#include "renderer/object_primitives.hpp"
#include "renderer/shapes/height_field.hpp"

namespace povtrace::render {

namespace {

// The object's primitives as build_render_scene makes them, without materials (trace() and inside() never shade):
// a union POV-Ray splits becomes its children, other CSG and clipped or bounded objects one CSG node.
void add_geometry(const Object& o, const BuildContext& context, std::vector<Primitive>& out) {
  if (splits_into_children(o)) {
    for (const auto& child : std::get<Csg>(o.shape).children) add_geometry(child, context, out);
    return;
  }
  if (needs_csg_node(o)) {
    out.push_back(build_csg_node(
        o, [&](const Object& leaf, bool, std::vector<Primitive>& dst) { add_shape_primitives(leaf, 0, 0, context, dst); },
        context));
    return;
  }
  add_shape_primitives(o, 0, 0, context, out);
}

class PreparedPrimitives final : public PreparedObject {
 public:
  explicit PreparedPrimitives(std::vector<Primitive> primitives) : accelerator_(std::move(primitives)) {}

  // POV-Ray's Find_Intersection keeps the nearest intersection at a depth of at least MIN_ISECT_DEPTH; its
  // Parse_Trace then takes the normal of the object hit (for CSG the child whose surface it is), reversed when
  // that object is inverted.
  std::optional<TracedHit> trace(Vec3 origin, Vec3 unit_direction) const override {
    const Ray ray{origin, unit_direction, ray_kind::other};
    const Hit hit = accelerator_.closest_hit(ray, tolerance::min_isect_depth, tolerance::bound_huge);
    if (!hit.found()) return std::nullopt;
    const Vec3 point = hit_point(ray, hit.surface);
    const Vec3 normal = surface_normal(hit.surface, point);
    return TracedHit{point, hit.surface.leaf->inverse ? -normal : normal};
  }

  // Inside_Object of a split union: inside any of its children. Every primitive is asked, not only those whose
  // bounds hold the point: some insides reach beyond the bounds (below a height field, an inverse object).
  bool inside(Vec3 point) const override {
    for (const Primitive& p : accelerator_.primitives())
      if (render::inside(p, point)) return true;
    return false;
  }

 private:
  Accelerator accelerator_;
};

}  // namespace

// A prepared object's meshes are shared among its own parts only: the parser keeps the prepared object while it
// traces it, and the render builds its own.
std::unique_ptr<const PreparedObject> RendererGeometry::prepare(const Object& object, int noise_generator) const {
  SharedMeshes meshes;
  std::vector<Primitive> primitives;
  add_geometry(object, BuildContext{noise_generator, meshes, *this}, primitives);
  return std::make_unique<PreparedPrimitives>(std::move(primitives));
}

// The samples as the render reads them: the height field's data, built alone without smoothing (normals do not
// change the box). An image file's extent is kept per file, modification time and water level.
HeightFieldExtent RendererGeometry::height_field_extent(const HeightField& h, int noise_generator) const {
  const bool from_file = !h.samples && !h.pigment_function;
  std::string key;
  if (from_file) {
    std::error_code error;   // an unreadable file gets no time here and fails below, when it is read
    const auto written = std::filesystem::last_write_time(h.file, error);
    key = h.file + '\n' + std::to_string(written.time_since_epoch().count()) + '\n' + std::to_string(h.water_level);
    const std::lock_guard<std::mutex> lock(mutex_);
    if (const auto found = file_extents_.find(key); found != file_extents_.end()) return found->second;
  }
  Object o;
  HeightField unsmoothed = h;
  unsmoothed.smooth = false;
  o.shape = std::move(unsmoothed);
  SharedMeshes meshes;
  std::vector<Primitive> primitives;
  add_shape_primitives(o, 0, 0, BuildContext{noise_generator, meshes, *this}, primitives);
  const auto& d = static_cast<const HeightFieldData&>(*primitives.at(0).data);
  const HeightFieldExtent extent{d.width, d.depth, d.bottom, d.top};
  if (from_file) {
    const std::lock_guard<std::mutex> lock(mutex_);
    file_extents_.emplace(key, extent);
  }
  return extent;
}

}  // namespace povtrace::render
