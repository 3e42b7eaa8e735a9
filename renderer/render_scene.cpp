#include "renderer/render_scene.hpp"
#include "renderer/scene_scale.hpp"
#include "renderer/render.hpp"

#include "renderer/csg_build.hpp"
#include "renderer/located_error.hpp"
#include "renderer/mesh_camera.hpp"
#include "renderer/object_geometry.hpp"
#include "renderer/object_primitives.hpp"
#include "renderer/shapes/triangle_shapes.hpp"

#include <cmath>
#include <map>
#include <stdexcept>
#include <unordered_map>

#include "renderer/pattern/normal_perturbation.hpp"
#include "renderer/media/render_media.hpp"
#include "renderer/photons/photon_shoot.hpp"
#include "renderer/pattern/render_pigment.hpp"
#include "renderer/pattern/render_texture.hpp"

namespace povtrace::render {

namespace {
Material make_material(const Texture& texture, const std::optional<Interior>& interior, bool uv_mapping,
                       ImageCache& images, bool quick_colours) {
  Material m;
  m.interior = interior.value_or(Interior{});
  m.texture = build_render_texture(texture, images);
  // Opaque if some layer's pigment has no filter/transmit anywhere (pipeline §3); with quick colours too, as
  // POV-Ray's parser sets its opaque flag from the pigments themselves.
  m.opaque = texture_is_opaque(m.texture);
  if (quick_colours) m.texture = build_render_texture(texture, images, true);
  m.uv_mapping = uv_mapping;
  m.needs_uv = uv_mapping || texture_reads_uv(m.texture);
  m.needs_surface = texture_reads_surface(m.texture);
  return m;
}

RenderLight make_light(const Light& l) {
  RenderLight r;
  r.light = l;
  r.colour = rgb_of(l.colour);
  const Vec3 axis = l.point_at - l.location;
  if (l.parallel) r.parallel_direction = length(axis) > 0 ? -normalize(axis) : Vec3{0, 0, -1};
  // A spotlight or cylinder light whose point_at is its location has no direction: POV-Ray keeps the zero vector,
  // so every angle test fails and the light lights nothing.
  if (l.cylinder) r.spot_axis = length(axis) > 0 ? normalize(axis) : Vec3{0, 0, 0};
  if (l.spotlight && !l.cylinder) {
    r.spot_axis = length(axis) > 0 ? normalize(axis) : Vec3{0, 0, 0};
    r.cos_radius = std::cos(l.radius * M_PI / 180.0);
    r.cos_falloff = std::cos(l.falloff * M_PI / 180.0);
  }
  r.fades = l.fade_power > 0 && std::fabs(l.fade_distance) > tolerance::epsilon;
  return r;
}

// Objects sharing one texture (and no interior of their own) share one material.
class MaterialTable {
 public:
  MaterialTable(std::vector<Material>& materials, ImageCache& images, bool quick_colours,
                const photons::PhotonGroups* photon_groups)
      : materials_(materials), images_(images), quick_colours_(quick_colours), photon_groups_(photon_groups) {}
  std::uint32_t material_for(const Object& o) {
    const Key key{o.texture.get(), o.uv_mapping};
    // An object with an interior or photon flags of its own gets a material of its own.
    const std::uint32_t target = photon_target_of(o);
    const bool shareable = !o.interior && !o.interior_texture && o.photons == ObjectPhotons{} &&
                           target == kNoPhotonTarget && o.light_groups.empty() && !o.no_global_lights;
    auto found = shareable ? shared_.find(key) : shared_.end();
    if (found != shared_.end()) return found->second;
    materials_.push_back(make_material(*o.texture, o.interior, o.uv_mapping, images_, quick_colours_));
    materials_.back().photons = o.photons;
    materials_.back().photon_target = target;
    set_lights(materials_.back(), o);
    if (o.interior_texture) {
      // POV-Ray's opaque flag needs both textures opaque (Post_Process): a shadow ray may leave through the inside.
      Material inside = make_material(*o.interior_texture, o.interior, o.uv_mapping, images_, quick_colours_);
      inside.photons = o.photons;
      inside.photon_target = target;
      set_lights(inside, o);
      materials_.back().opaque = materials_.back().opaque && inside.opaque;
      materials_.back().interior_material = static_cast<std::uint32_t>(materials_.size());
      materials_.push_back(std::move(inside));
      return static_cast<std::uint32_t>(materials_.size() - 2);
    }
    const auto index = static_cast<std::uint32_t>(materials_.size() - 1);
    if (shareable) shared_.emplace(key, index);
    return index;
  }
  // A mesh placement's own textures, as consecutive materials (the index of the first is returned).
  std::uint32_t append(const std::vector<std::shared_ptr<const Texture>>& textures, const Object& o) {
    const auto first = static_cast<std::uint32_t>(materials_.size());
    for (const auto& t : textures) {
      materials_.push_back(make_material(*t, o.interior, o.uv_mapping, images_, quick_colours_));
      materials_.back().photons = o.photons;
      materials_.back().photon_target = photon_target_of(o);
      set_lights(materials_.back(), o);
    }
    return first;
  }

 private:
  static void set_lights(Material& m, const Object& o) {
    m.global_lights = !o.no_global_lights;
    m.light_groups = o.light_groups;
  }
  std::uint32_t photon_target_of(const Object& o) const {
    if (!photon_groups_) return kNoPhotonTarget;
    const auto it = photon_groups_->group_of.find(&o);
    return it == photon_groups_->group_of.end() ? kNoPhotonTarget : it->second;
  }
  // A texture placed with and without uv_mapping makes two materials.
  using Key = std::pair<const Texture*, bool>;
  struct KeyHash {
    std::size_t operator()(const Key& k) const { return std::hash<const Texture*>()(k.first) ^ (k.second ? 1u : 0u); }
  };
  std::vector<Material>& materials_;
  ImageCache& images_;
  bool quick_colours_;
  const photons::PhotonGroups* photon_groups_;
  std::unordered_map<Key, std::uint32_t, KeyHash> shared_;
};

// A union is its children: every intersection of every child is kept (§10), which is what placing the
// children side by side gives (POV-Ray splits such unions too). The parser has already moved the union's
// transforms and inherited textures into the children. Other CSG, and clipped or bounded objects, become one
// CSG node (csg_build.hpp) whose leaves are built by add_primitives like any other shape.
// A mesh's triangle textures, or a blob's component textures (a component without one shades with the blob's
// texture), as consecutive materials of the primitive just built from `o`.
void attach_element_materials(const Object& o, MaterialTable& materials, Primitive& built) {
  if (const auto* mesh = std::get_if<Mesh>(&o.shape)) {
    built.element_materials = materials.append(mesh->textures, o);
  } else if (const auto* blob = std::get_if<Blob>(&o.shape); blob && !blob->textures.empty()) {
    std::vector<std::shared_ptr<const Texture>> textures = blob->textures;
    for (auto& t : textures)
      if (!t) t = o.texture;
    built.element_materials = materials.append(textures, o);
  }
}

void add_object(const Object& o, std::uint32_t object_index, MaterialTable& materials, const BuildContext& context,
                std::vector<Primitive>& out) {
  if (splits_into_children(o)) {
    for (const auto& child : std::get<Csg>(o.shape).children) add_object(child, object_index, materials, context, out);
    return;
  }
  if (needs_csg_node(o)) {
    Primitive node = build_csg_node(
        o,
        [&](const Object& leaf, bool shaded, std::vector<Primitive>& dst) {
          add_shape_primitives(leaf, shaded ? materials.material_for(leaf) : 0, object_index, context, dst);
          if (shaded && std::holds_alternative<Blob>(leaf.shape)) attach_element_materials(leaf, materials, dst.back());
        },
        context);
    node.material = materials.material_for(o);   // only for whole-object checks; hits shade their leaf's material
    node.object = object_index;
    out.push_back(std::move(node));
    return;
  }
  add_shape_primitives(o, materials.material_for(o), object_index, context, out);
  attach_element_materials(o, materials, out.back());
}


// Whether some object (a CSG child included) has no_image or no_reflection. For the scene's list and CSG children.
// no_radiosity counts only where radiosity is rendered.
template <class ObjectList>
bool any_ray_flags(const ObjectList& objects, bool radiosity) {
  for (const Object& o : objects) {
    if (o.no_image || o.no_reflection || (radiosity && o.no_radiosity)) return true;
    if (const auto* csg = std::get_if<Csg>(&o.shape); csg && any_ray_flags(csg->children, radiosity)) return true;
  }
  return false;
}
}  // namespace

// Every object has an interior in POV-Ray; a camera ray starts inside those whose object contains its origin
// (POV-Ray's containing-interiors list, §4).
std::vector<InteriorRef> RenderScene::containing_interiors(Vec3 point) const {
  std::vector<InteriorRef> out;
  accelerator.for_each_containing(point, [&](std::uint32_t i) {
    const Primitive& p = accelerator.primitives()[i];
    out.push_back(InteriorRef{p.object, &materials[p.material].interior, materials[p.material].media.get()});
  });
  return out;
}

namespace {
RenderScene build_scene(const SceneDescription& scene, const BuildOptions& options, bool may_rescale);

// The specialised paths this scene allows (render_scene.hpp Specialisation), among those the build may use.
Specialisation choose_specialisation(const RenderScene& r, const SpecialisationChoice& c) {
  Specialisation s;
  s.nearest_shadow_first = c.nearest_shadow_first && r.any_casts_shadow;
  s.no_shadow_rays = c.no_shadow_rays && !r.any_casts_shadow;
  s.embree_meshes = c.embree_meshes;
  return s;
}
}  // namespace

namespace {
// Radiosity's render-ready settings; in a 3.7 scene the `ambient · ambient_light` term goes (study §1.1): the
// tracer's ambient term then multiplies by a black ambient_light.
void add_radiosity(RenderScene& r, const SceneDescription& scene) {
  auto rad = std::make_shared<radiosity::RenderRadiosity>(radiosity::make_render_radiosity(scene));
  if (rad->drop_ambient) r.settings.ambient_light = Colour{0, 0, 0};
  if (rad->settings.direction_pool < kRadiosityTableDirections)
    r.warnings.push_back("radiosity: a direction pool below 1600 (count's second value) uses POV-Ray's fixed "
                         "table, which povtrace does not have; the Halton pool of that size is used instead");
  r.radiosity = std::move(rad);
}
}  // namespace

namespace {
// The interiors' media and the atmosphere's, ready for sampling: materials with one media list share its sampling
// form. Their densities use the scene's noise generator as pigments do.
void add_media(RenderScene& r, const SceneDescription& scene, ImageCache& images, bool quick_colours, int generator) {
  std::map<const std::vector<Media>*, std::shared_ptr<const MediaSet>> built;
  const auto build = [&](const std::vector<Media>& media) {
    auto set = std::make_shared<MediaSet>();
    for (const Media& m : media) {
      set->media.push_back(build_render_media(m, &images, quick_colours));
      for (RenderPigment& d : set->media.back().densities) {
        set_generator(d, generator == 1 ? NoiseGenerator::original : NoiseGenerator::range_corrected);
        set_function_generator(d, generator);
      }
    }
    return std::shared_ptr<const MediaSet>(std::move(set));
  };
  for (Material& m : r.materials) {
    const auto& media = m.interior.media;
    if (!media || media->empty()) continue;
    auto& slot = built[media.get()];
    if (!slot) slot = build(*media);
    m.media = slot;
    r.any_interior_media = true;
  }
  if (!scene.atmosphere.empty()) r.atmosphere = build(scene.atmosphere);
}
}  // namespace

RenderScene build_render_scene(const SceneDescription& scene, const BuildOptions& options) {
  if (options.povray_tolerances) return build_scene(with_world_space_spheres(scene), options, false);
  return build_scene(scene, options, true);
}

namespace {
RenderScene build_scene(const SceneDescription& scene, const BuildOptions& options, bool may_rescale) {
  RenderScene r;
  std::vector<Primitive> primitives;
  primitives.reserve(scene.objects.size());
  ImageCache images;
  // Photon targets and the objects in their trees, whose materials name their target.
  const bool shoot_photons = scene.photons && options.quality >= 9;
  const photons::PhotonGroups photon_groups = shoot_photons ? photons::find_photon_groups(scene) : photons::PhotonGroups{};
  MaterialTable materials(r.materials, images, options.quick_colours, shoot_photons ? &photon_groups : nullptr);
  // The scene's noise generator as it stands when the scene ends (POV-Ray: 1 before #version 3.5, 2 from then on).
  const int generator = scene.settings.noise_generator.value_or(scene.language_version < 350 ? 1 : 2);
  SharedMeshes meshes;              // one BVH per declared mesh, however often it is placed
  const RendererGeometry geometry;  // height-field extents for POV-Ray's culling boxes, kept per build
  const BuildContext context{generator, meshes, geometry};
  for (std::size_t i = 0; i < scene.objects.size(); ++i)
    add_object(scene.objects[i], static_cast<std::uint32_t>(i), materials, context, primitives);
  if (may_rescale) {
    // A scene far from the ordinary scale is rendered as its rescaled twin (scene_scale.hpp).
    if (const double k = normalizing_scale(object_sizes(primitives, scene.camera.location)); k != 1.0) {
      RenderScene twin = build_scene(scaled_scene(scene, k), options, false);
      twin.scale = k;
      return twin;
    }
  }
  for (const auto& p : primitives) r.any_casts_shadow = r.any_casts_shadow || p.casts_shadow;
  const bool radiosity = scene.radiosity && options.quality >= 9;
  r.any_ray_flags = any_ray_flags(scene.objects, radiosity);
  for (const auto& p : primitives) {
    const Material& m = r.materials[p.material];
    const Interior& in = m.interior;
    if (!m.opaque && p.casts_shadow && in.fade_power > 0 && std::fabs(in.fade_distance) > tolerance::epsilon)
      r.any_shadow_fade = true;
  }
  use_noise_generator(r.materials, static_cast<NoiseGenerator>(generator));
  add_media(r, scene, images, options.quick_colours, generator);
  r.specialisation = choose_specialisation(r, options.specialise);
  if (r.specialisation.embree_meshes)
    for (Primitive& p : primitives)
      if (p.type == ShapeType::mesh) shapes::prepare_embree_mesh(p);
  r.accelerator = Accelerator(std::move(primitives));
  r.wave_sources = make_wave_sources(scene.settings.number_of_waves);
  r.camera_interiors = r.containing_interiors(scene.camera.location);
  r.fogs = scene.fogs;
  for (const Rainbow& rainbow : scene.rainbows) {
    if (!rainbow.colour_map || rainbow.distance == 0.0 || rainbow.width == 0.0) continue;   // ComputeRainbow skips
    r.rainbows.push_back({rainbow, build_render_pigment(*rainbow.colour_map, &images, options.quick_colours)});
  }
  r.noise_generator = static_cast<NoiseGenerator>(generator);
  for (const auto& l : scene.lights) {
    r.lights.push_back(make_light(l));
    if (!l.projected_through.empty())
      r.lights.back().projected_through = RendererGeometry().prepare(l.projected_through.front(), generator);
  }
  r.camera = make_render_camera(scene.camera);
  if (scene.camera.projection == Projection::mesh && scene.camera.mesh)
    r.camera.mesh = make_mesh_camera(*scene.camera.mesh, scene.camera.location.z, scene.camera.direction.z);
  if (scene.camera.normal) {
    auto normal = std::make_shared<RenderNormal>(build_render_normal(*scene.camera.normal, &images));
    set_normal_generator(*normal, static_cast<NoiseGenerator>(generator));
    r.camera.normal = std::move(normal);
    r.camera.normal_waves = r.wave_sources;
  }
  r.settings = scene.settings;
  if (radiosity) add_radiosity(r, scene);
  r.language_version = scene.language_version;
  // Background (pipeline §5) as POV-Ray's parser leaves it.
  const Colour& bg = scene.background;
  r.output_alpha = options.output_alpha;
  if (scene.language_version < 370)
    r.background_colour = Colour{bg.r, bg.g, bg.b, 0, options.output_alpha ? 1.0 : 0.0};
  else if (options.output_alpha)
    r.background_colour = bg;
  else
    r.background_colour = Colour{bg.r * (1.0 - bg.t), bg.g * (1.0 - bg.t), bg.b * (1.0 - bg.t), 0, 0};
  if (scene.sky_sphere) {
    for (const Pigment& p : scene.sky_sphere->pigments) {
      r.sky_pigments.push_back(build_render_pigment(p, &images, options.quick_colours));
      set_generator(r.sky_pigments.back(), generator == 1 ? NoiseGenerator::original : NoiseGenerator::range_corrected);
      set_function_generator(r.sky_pigments.back(), generator);   // functions read the scene's, Perlin's too
    }
    r.sky_emission = rgb_of(scene.sky_sphere->emission);
    r.sky_transformed = !(scene.sky_sphere->world_from_sky == Matrix::identity());
    if (r.sky_transformed) r.sky_from_world = scene.sky_sphere->world_from_sky.inverse();
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
  // Photons last: the photon pass traces the finished scene. POV-Ray shoots them only at +Q9 (Q_ADVANCED_LIGHT,
  // as radiosity); below it the scene renders as without its photons block.
  if (shoot_photons) {
    r.photon_settings = scene.photons;
    r.photon_targets = photons::bound_photon_targets(photon_groups, r.accelerator, context);
    r.photons = photons::shoot_photons(r, options.quality, options.threads, r.warnings);
  }
  return r;
}
}  // namespace

bool SpecialisationChoice::turn_off(std::string_view name) {
  if (name == "all") {
    nearest_shadow_first = no_shadow_rays = embree_meshes = false;
    return true;
  }
  if (name == "nearest-shadow-first") nearest_shadow_first = false;
  else if (name == "no-shadow-rays") no_shadow_rays = false;
  else if (name == "embree-meshes") embree_meshes = false;
  else return false;
  return true;
}

std::string SpecialisationChoice::names() {
  return "nearest-shadow-first, no-shadow-rays, embree-meshes";
}

}  // namespace povtrace::render
