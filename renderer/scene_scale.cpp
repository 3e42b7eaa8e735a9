#include "renderer/scene_scale.hpp"

#include <algorithm>
#include <cmath>

#include "scene/description_transforms.hpp"

namespace povtrace::render {

namespace {
// The ordinary range of object sizes, where POV-Ray's absolute tolerances (1e-4, 1e-3) are small against the
// objects and its maximum distance (1e7) far beyond them; rescaled scenes land near the middle of it, in log terms.
constexpr double kSmallest = 0.05, kLargest = 1e4, kTarget = 2;

// Media coefficients are per unit length: lengths k times longer need coefficients k times smaller (their
// densities already moved with the objects' transforms, or below for the atmosphere).
void scale_media_coefficients(Media& m, double k) {
  for (Colour* c : {&m.absorption, &m.emission, &m.scattering}) {
    c->r /= k;
    c->g /= k;
    c->b /= k;
  }
}

void scale_interiors(Object& o, double k) {
  if (o.interior) {
    o.interior->fade_distance *= k;
    if (o.interior->media) {
      auto media = std::make_shared<std::vector<Media>>(*o.interior->media);
      for (Media& x : *media) scale_media_coefficients(x, k);
      o.interior->media = std::move(media);
    }
  }
  if (auto* csg = std::get_if<Csg>(&o.shape))
    for (Object& child : csg->children) scale_interiors(child, k);
}

// POV-Ray's box of a placed object as its Transform would remake it after the scaling (PlacedBox::moved: a power of
// two scales the box exactly as it scales the shape).
void scale_placed_box(Object& o, const Matrix& m) {
  if (auto* csg = std::get_if<Csg>(&o.shape))   // the children of a union the parser placed one by one
    for (Object& child : csg->children) scale_placed_box(child, m);
  if (!o.placed_box || !o.placed_box->known) return;
  PlacedBox& placed = *o.placed_box;
  if (!placed.moved) {
    placed.box = ExtentBox::huge();
    return;
  }
  placed.moved = placed.moved->transformed(m);
  placed.box = *placed.moved;
}

void fold_sphere_transforms(Object& o) {
  if (auto* sphere = std::get_if<Sphere>(&o.shape); sphere && !sphere->ellipsoid) {
    const Matrix& m = o.world_from_object;
    sphere->centre = m.point(sphere->centre);
    sphere->radius *= length(m.vector({1, 0, 0}));   // rotations and uniform scales only: |m·x| is the scale
    o.world_from_object = Matrix::identity();
  }
  if (auto* csg = std::get_if<Csg>(&o.shape))
    for (Object& child : csg->children) fold_sphere_transforms(child);
  for (Object& clip : o.clipped_by) fold_sphere_transforms(clip);
  for (Object& bound : o.bounded_by) fold_sphere_transforms(bound);
}
}  // namespace

SceneDescription with_world_space_spheres(const SceneDescription& scene) {
  SceneDescription s = scene;
  for (Object& o : s.objects) fold_sphere_transforms(o);
  for (Light& l : s.lights)
    for (Object& o : l.looks_like) fold_sphere_transforms(o);
  return s;
}

ObjectSizes object_sizes(const std::vector<Primitive>& primitives, Vec3 camera) {
  ObjectSizes sizes = object_sizes(primitives);
  sizes.reaches_max_distance = false;
  for (const Primitive& p : primitives) {
    const Bounds b = world_bounds(p);
    if (b.empty()) continue;
    if (!b.finite()) {
      sizes.reaches_max_distance = true;
      break;
    }
    const Vec3 far{std::max(std::fabs(b.lo.x - camera.x), std::fabs(b.hi.x - camera.x)),
                   std::max(std::fabs(b.lo.y - camera.y), std::fabs(b.hi.y - camera.y)),
                   std::max(std::fabs(b.lo.z - camera.z), std::fabs(b.hi.z - camera.z))};
    if (length(far) > 0.5 * tolerance::max_distance) {
      sizes.reaches_max_distance = true;
      break;
    }
  }
  return sizes;
}

ObjectSizes object_sizes(const std::vector<Primitive>& primitives) {
  std::vector<double> sizes;
  sizes.reserve(primitives.size());
  for (const Primitive& p : primitives)
    if (const Bounds b = world_bounds(p); b.finite() && !b.empty()) sizes.push_back(length(b.hi - b.lo));
  if (sizes.empty()) return {};
  std::sort(sizes.begin(), sizes.end());
  return ObjectSizes{sizes.front(), sizes[(sizes.size() - 1) / 2], sizes.back()};
}

double normalizing_scale(const ObjectSizes& sizes) {
  const bool all_tiny = sizes.largest > 0 && sizes.largest < kSmallest;
  const bool all_huge = std::isfinite(sizes.smallest) && sizes.smallest > kLargest && sizes.reaches_max_distance;
  if (!all_tiny && !all_huge) return 1.0;
  return std::exp2(std::round(std::log2(kTarget / sizes.median)));
}

SceneDescription scaled_scene(const SceneDescription& scene, double k) {
  SceneDescription s = scene;
  const Matrix m = Matrix::scaling({k, k, k});
  for (Object& o : s.objects) {
    transform_object(o, m);
    scale_placed_box(o, m);
    scale_interiors(o, k);
  }
  for (Light& l : s.lights) {
    transform_light(l, m);
    l.fade_distance *= k;
    if (l.cylinder) {
      l.radius *= k;
      l.falloff *= k;
    }
  }
  Camera& c = s.camera;
  // A mesh camera's location is an offset along its faces' normals in mesh space, which the meshes' scaling below
  // scales already; its rays come from the meshes.
  if (c.mesh) {
    auto mesh = std::make_shared<MeshCamera>(*c.mesh);
    for (MeshCameraMesh& cm : mesh->meshes) {
      cm.world_from_object = cm.world_from_object * m;
      cm.transformed = true;
    }
    c.mesh = std::move(mesh);
  }
  if (c.projection != Projection::mesh) c.location = c.location * k;
  c.direction = c.direction * k;
  c.up = c.up * k;
  c.right = c.right * k;
  for (Media& a : s.atmosphere) {
    for (Pigment& d : a.densities) transform_pattern(d, m);
    scale_media_coefficients(a, k);
  }
  if (s.photons) {   // photon spacing and gather radii are world distances
    s.photons->spacing *= k;
    if (s.photons->radius > 0) s.photons->radius *= k;
    if (s.photons->media_radius > 0) s.photons->media_radius *= k;
  }
  for (Fog& f : s.fogs) {
    f.distance *= k;
    f.alt *= k;
    f.offset *= k;
  }
  for (Rainbow& r : s.rainbows) r.distance *= k;   // directions and angles stay
  return s;
}

}  // namespace povtrace::render
