#include "renderer/object_primitives.hpp"

#include <cstdint>

#include "renderer/csg_build.hpp"
#include "renderer/shapes/shape_registry.hpp"

namespace povtrace::render {

void add_shape_primitives(const Object& o, std::uint32_t material, std::uint32_t object_index,
                          const BuildContext& context, std::vector<Primitive>& out) {
  Primitive* shape = shapes::append_shape(o.shape, o.world_from_object, context, out);
  if (!shape) return;   // a disc with a zero normal: POV-Ray renders nothing either
  Primitive& p = *shape;
  p.material = material;
  p.object = object_index;
  p.casts_shadow = !o.no_shadow;
  set_ray_flags(p, o);
  p.inverse = o.inverse;
  p.double_illuminate = o.double_illuminate;
  p.radiosity_importance = o.radiosity_importance ? static_cast<float>(*o.radiosity_importance) : -1.0f;
}

}  // namespace povtrace::render
