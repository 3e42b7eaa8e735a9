#include "renderer/render_scene.hpp"
#include "renderer/shapes/triangle_shapes.hpp"

#include <cmath>
#include <stdexcept>
#include <unordered_map>

namespace povtrace::render {

namespace {
RenderPigment make_pigment(const Pigment& p) {
  RenderPigment r;
  r.pattern = p.pattern;
  r.colour = p.colour;
  for (std::size_t i = 0; i < 2 && i < p.entries.size(); ++i) r.entries[i] = p.entries[i];
  r.transformed = !(p.world_from_pattern == Matrix::identity());
  if (r.transformed) r.pattern_from_world = p.world_from_pattern.inverse();
  return r;
}

bool pigment_has_transparency(const Pigment& p) {
  auto clear = [](const Colour& c) { return c.f != 0.0 || c.t != 0.0; };
  if (p.pattern == PatternKind::solid) return clear(p.colour);
  for (const auto& e : p.entries)
    if (clear(e)) return true;
  return false;
}

Material make_material(const Texture& texture, const std::optional<Interior>& interior) {
  Material m;
  m.interior = interior.value_or(Interior{});
  m.opaque = false;
  for (auto it = texture.layers.rbegin(); it != texture.layers.rend(); ++it) {
    RenderLayer layer;
    layer.pigment = make_pigment(it->pigment);
    layer.finish = it->finish;
    layer.specular_exponent = 1.0 / it->finish.roughness;
    layer.has_highlights = it->finish.phong != 0.0 || it->finish.specular != 0.0;
    // Opaque if some layer's pigment has no filter/transmit anywhere (pipeline §3).
    if (!pigment_has_transparency(it->pigment)) m.opaque = true;
    m.layers.push_back(layer);
  }
  return m;
}

RenderLight make_light(const Light& l) {
  RenderLight r;
  r.light = l;
  r.colour = rgb_of(l.colour);
  const Vec3 axis = l.point_at - l.location;
  if (l.parallel) r.parallel_direction = length(axis) > 0 ? -normalize(axis) : Vec3{0, 0, -1};
  if (l.spotlight) {
    r.spot_axis = length(axis) > 0 ? normalize(axis) : Vec3{0, 0, 1};
    r.cos_radius = std::cos(l.radius * M_PI / 180.0);
    r.cos_falloff = std::cos(l.falloff * M_PI / 180.0);
  }
  r.fades = l.fade_power > 0 && std::fabs(l.fade_distance) > tolerance::epsilon;
  return r;
}

// Flattens one description object into world-space primitives (one per shape for now).
void add_primitives(const Object& o, std::uint32_t material, std::uint32_t object_index,
                    std::vector<Primitive>& out) {
  Primitive p;
  p.material = material;
  p.object = object_index;
  p.casts_shadow = !o.no_shadow;
  p.inverse = o.inverse;
  p.transformed = !(o.world_from_object == Matrix::identity());
  p.world_from_object = o.world_from_object;
  if (p.transformed) p.object_from_world = o.world_from_object.inverse();
  if (const auto* s = std::get_if<Sphere>(&o.shape)) {
    p.type = ShapeType::sphere;
    p.a = s->centre;
    p.radius = s->radius;
  } else if (const auto* pl = std::get_if<Plane>(&o.shape)) {
    p.type = ShapeType::plane;
    p.a = pl->normal;
    p.radius = pl->distance;
  } else if (const auto* b = std::get_if<Box>(&o.shape)) {
    p.type = ShapeType::box;
    p.a = b->corner1;
    p.b = b->corner2;
  } else if (const auto* tri = std::get_if<Triangle>(&o.shape)) {
    p.type = ShapeType::triangle;
    shapes::set_up_triangle(p, *tri);
  } else if (const auto* poly = std::get_if<Polygon>(&o.shape)) {
    p.type = ShapeType::polygon;
    shapes::set_up_polygon(p, *poly);
  } else if (const auto* mesh = std::get_if<Mesh>(&o.shape)) {
    p.type = ShapeType::mesh;
    shapes::set_up_mesh(p, *mesh);
  } else {
    throw std::logic_error("CSG nodes are flattened by add_object and never reach add_primitives");
  }
  out.push_back(p);
}

// Objects sharing one texture (and no interior of their own) share one material.
class MaterialTable {
 public:
  explicit MaterialTable(std::vector<Material>& materials) : materials_(materials) {}
  std::uint32_t material_for(const Object& o) {
    auto found = o.interior ? shared_.end() : shared_.find(o.texture.get());
    if (found != shared_.end()) return found->second;
    materials_.push_back(make_material(*o.texture, o.interior));
    const auto index = static_cast<std::uint32_t>(materials_.size() - 1);
    if (!o.interior) shared_.emplace(o.texture.get(), index);
    return index;
  }
  // A mesh placement's own textures, as consecutive materials (the index of the first is returned).
  std::uint32_t append(const std::vector<std::shared_ptr<const Texture>>& textures,
                       const std::optional<Interior>& interior) {
    const auto first = static_cast<std::uint32_t>(materials_.size());
    for (const auto& t : textures) materials_.push_back(make_material(*t, interior));
    return first;
  }

 private:
  std::vector<Material>& materials_;
  std::unordered_map<const Texture*, std::uint32_t> shared_;
};

// A union is its children: every intersection of every child is kept (§10), which is what placing the
// children side by side gives. The parser has already moved the union's transforms and inherited textures
// into the children. Other CSG operations are refused by the parser until issue 4.
void add_object(const Object& o, std::uint32_t object_index, MaterialTable& materials, std::vector<Primitive>& out) {
  if (const auto* csg = std::get_if<Csg>(&o.shape)) {
    if (csg->kind != CsgKind::union_) throw std::logic_error("only CSG unions reach the renderer");
    for (const auto& child : csg->children) add_object(child, object_index, materials, out);
    return;
  }
  add_primitives(o, materials.material_for(o), object_index, out);
  if (const auto* mesh = std::get_if<Mesh>(&o.shape))
    out.back().element_materials = materials.append(mesh->textures, o.interior);
}
// Refraction uses ior/1 at every surface (each object seen from air). POV-Ray tracks the list of interiors
// a ray is in, which differs where refracting objects overlap or nest: say so instead of differing silently.
void warn_about_nested_refraction(const std::vector<Primitive>& primitives, const std::vector<Material>& materials,
                                  std::vector<std::string>& warnings) {
  std::vector<const Primitive*> refracting;
  for (const auto& p : primitives)
    if (materials[p.material].interior.ior != 1.0) refracting.push_back(&p);
  for (std::size_t i = 0; i < refracting.size(); ++i)
    for (std::size_t j = i + 1; j < refracting.size(); ++j) {
      const Bounds a = world_bounds(*refracting[i]), b = world_bounds(*refracting[j]);
      const bool overlap = a.lo.x <= b.hi.x && b.lo.x <= a.hi.x && a.lo.y <= b.hi.y && b.lo.y <= a.hi.y &&
                           a.lo.z <= b.hi.z && b.lo.z <= a.hi.z;
      if (overlap) {
        warnings.push_back("objects with an ior overlap or nest; povtrace refracts each surface as seen from air "
                           "(ior 1), while POV-Ray uses the ior of the enclosing object: the image may differ there");
        return;
      }
    }
}
}  // namespace

RenderScene build_render_scene(const SceneDescription& scene, const BuildOptions& options) {
  RenderScene r;
  std::vector<Primitive> primitives;
  primitives.reserve(scene.objects.size());
  MaterialTable materials(r.materials);
  for (std::size_t i = 0; i < scene.objects.size(); ++i)
    add_object(scene.objects[i], static_cast<std::uint32_t>(i), materials, primitives);
  for (const auto& p : primitives) r.any_casts_shadow = r.any_casts_shadow || p.casts_shadow;
  warn_about_nested_refraction(primitives, r.materials, r.warnings);
  r.accelerator = Accelerator(std::move(primitives));
  for (const auto& l : scene.lights) r.lights.push_back(make_light(l));
  r.camera = RenderCamera{scene.camera.projection, scene.camera.location, scene.camera.direction, scene.camera.up,
                          scene.camera.right};
  r.settings = scene.settings;
  r.language_version = scene.language_version;
  // Background (pipeline §5). 3.7 scenes: a miss returns the premultiplied rgb·(1 − t) with or without alpha output
  // (POV-Ray +UA writes rgbt <.2,.4,.6,.5> as (0.1,0.2,0.3) α 0.5), transmit t only with alpha. Older scenes clear
  // the background's transmit without alpha output (full rgb) and set it to 1 with alpha (a miss is (0,0,0) α 0).
  const Colour& bg = scene.background;
  if (scene.language_version < 370) {
    r.background = options.output_alpha ? Rgb{0, 0, 0} : rgb_of(bg);
    r.background_transmit = options.output_alpha ? 1.0 : 0.0;
  } else {
    r.background = rgb_of(bg) * (1.0 - bg.t);
    r.background_transmit = options.output_alpha ? bg.t : 0.0;
  }
  // Working gamma (pipeline §6): assumed_gamma if given; #version ≥ 3.7 alone means 1.0; otherwise legacy.
  if (scene.settings.assumed_gamma) {
    r.gamma_mode = GammaMode::power;
    r.assumed_gamma = *scene.settings.assumed_gamma;
  } else if (scene.version_given && scene.language_version >= 370) {
    r.gamma_mode = GammaMode::power;
    r.assumed_gamma = 1.0;
  } else {
    r.gamma_mode = GammaMode::legacy_srgb;
  }
  return r;
}

}  // namespace povtrace::render
