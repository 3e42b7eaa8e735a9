// Builds a blob's elements from its description as POV-Ray 3.7's Make_Blob does (source/backend/shape/blob.cpp,
// 3.7-stable): the component list is kept in reverse written order (POV-Ray prepends each component while parsing),
// each component of strength s and squared radius R gets the density coefficients s/R², −2s/R, s, and a cylinder
// becomes three elements: the cylinder and a hemisphere at each end, all placed by the cylinder's frame (the
// canonical transform taking +z to its axis, unit scale) followed by its own transforms.
#include "renderer/shapes/blob.hpp"
#include "renderer/shapes/quadric_shapes.hpp"

namespace povtrace::render {

std::shared_ptr<BlobData> blob_data(const Blob& b) {
  auto d = std::make_shared<BlobData>();
  d->threshold = b.threshold;
  d->sturm = b.sturm;
  d->textured_components = static_cast<std::uint32_t>(b.textures.size());
  for (auto it = b.components->rbegin(); it != b.components->rend(); ++it) {
    BlobElement e;
    e.component = static_cast<std::uint32_t>(b.components->rend() - it - 1);
    e.centre = it->centre;
    e.radius2 = it->radius2;
    const double s = it->strength, r2 = it->radius2;
    e.c[0] = s / (r2 * r2);
    e.c[1] = -(2.0 * s) / r2;
    e.c[2] = s;
    Matrix blob_from_element = it->transform;
    if (it->kind == BlobComponentKind::cylinder) {
      const Vec3 axis = it->apex - it->centre;
      e.length = length(axis);
      blob_from_element = canonical_frame(it->centre, axis / e.length, 1.0, 1.0) * it->transform;
    }
    e.transformed = it->kind != BlobComponentKind::sphere;
    if (e.transformed) e.element_from_blob = blob_from_element.inverse();
    if (it->kind == BlobComponentKind::cylinder) {
      e.kind = BlobElement::Kind::cylinder;
      d->elements.push_back(e);
      e.kind = BlobElement::Kind::base_hemisphere;
      d->elements.push_back(e);
      e.kind = BlobElement::Kind::apex_hemisphere;
      d->elements.push_back(e);
    } else {
      e.kind = it->kind == BlobComponentKind::sphere ? BlobElement::Kind::sphere : BlobElement::Kind::ellipsoid;
      d->elements.push_back(e);
    }
  }
  return d;
}

}  // namespace povtrace::render
