// Whitted tracing with POV-Ray 3.7's shading (povray-pixel-pipeline.md §2–§5). Comments cite the section of
// that document whose behaviour each step reproduces.
#include "renderer/tracer.hpp"

#include "renderer/shapes/blob.hpp"
#include "renderer/render.hpp"
#include "renderer/shading_helpers.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstring>

#include "renderer/pattern/normal_perturbation.hpp"
#include "renderer/pattern/pattern.hpp"
#include "renderer/pattern/render_texture.hpp"

namespace povtrace::render {

namespace {
Rgb mul(Rgb a, Rgb b) { return {a.x * b.x, a.y * b.y, a.z * b.z}; }


constexpr double kPhongCutoff = 0.0008;       // phong highlights with size ≥ 60 vanish below this (§2)
constexpr double kPhongCutoffSize = 60.0;
}  // namespace

Quality Quality::at_level(int level) {
  Quality q;
  q.full_ambient = level <= 1;
  q.shadows = level >= 4;
  q.area_lights = level >= 5;
  q.refraction = level >= 6;
  q.reflection = q.normals = level >= 8;
  q.fog = level >= 9;
  return q;
}

Tracer::Tracer(const RenderScene& scene, ShadingModel model, Quality quality)
    : scene_(scene), model_(model), quality_(quality), fog_(quality.fog && !scene.fogs.empty()),
      media_(quality.fog && (scene.atmosphere || scene.any_interior_media)),
      rainbows_(quality.fog && !scene.rainbows.empty()),
      transmit_bailout_(quality.refraction ? scene.settings.adc_bailout : HUGE_VAL),
      max_level_(scene.settings.max_trace_level), adc_bailout_(scene.settings.adc_bailout) {
  if (quality.fog && (scene.atmosphere || !scene.fogs.empty()))
    for (const RenderLight& l : scene.lights)
      shadow_atmosphere_ = shadow_atmosphere_ || (l.light.media_interaction && l.light.media_attenuation);
  if (scene.photon_settings) {
    photon_map_ = scene.photons.get();
    photon_max_level_ = scene.photon_settings->max_trace_level.value_or(scene.settings.max_trace_level);
    photon_adc_ = scene.photon_settings->adc_bailout.value_or(scene.settings.adc_bailout);
  }
  if (scene.radiosity) {
    gatherer_ = std::make_unique<radiosity::Gatherer>(*scene.radiosity, scene.camera.location);
    sample_volume_ = scene.radiosity->settings.media;
  }
}

void Tracer::begin_block(int tile, int pass) {
  forget_shadow_cache();
  if (gatherer_) gatherer_->begin_block(tile, pass);
}

// x^e for the light falloffs: the usual exponents 1 and 2 without a pow call (same values: pow(x, 1) is x, and
// x·x is x² correctly rounded, as glibc's pow is in practice; the reference images were compared bit for bit).
namespace {
double power(double x, double e) {
  if (e == 1.0) return x;
  if (e == 2.0) return x * x;
  return std::pow(x, e);
}
}  // namespace

double metallic_fade(double x) {
  const double d = x - 1.12;
  return std::clamp(0.014567225 / (d * d) - 0.011612903, 0.0, 1.0);
}

Radiance Tracer::trace_camera_ray(const Ray& ray, bool pretrace) {
  ++counts_.camera;
  RayState state;
  state.alpha_background = scene_.output_alpha;
  state.pretrace = pretrace;
  // A perspective camera's rays all start at its location; an orthographic camera's start across its image
  // plane, so POV-Ray finds the containing objects for each of them.
  if (origins_vary(scene_.camera)) {
    for (const InteriorRef& r : scene_.containing_interiors(ray.origin)) state.interiors.append(r);
  } else {
    for (const InteriorRef& r : scene_.camera_interiors) state.interiors.append(r);
  }
  if (scene_.any_ray_flags) {   // no_image / no_reflection: a camera ray is POV-Ray's primary ray
    Ray primary = ray;
    primary.kind = ray_kind::primary;
    return trace(primary, 1, 1.0, state);
  }
  return trace(ray, 1, 1.0, state);
}

// Levels beyond max_trace_level and rays lighter than adc_bailout yield black, not the background (§4).
Radiance Tracer::trace(const Ray& ray, int level, double weight, const RayState& state) {
  if (level > max_level_ || weight < adc_bailout_) return {};
  const Hit hit = scene_.accelerator.closest_hit(ray, tolerance::min_isect_depth, tolerance::bound_huge);
  Radiance r =
      hit.found() ? shade_hit(ray, hit.surface, level, weight, state) : background(ray.direction, state);
  // Media and fog reach rays outside non-hollow objects only (POV-Ray's hollow rays); a miss is BOUND_HUGE away
  // (hit.t). Radiosity sample rays see them only with radiosity's `media on`.
  const bool volume = state.interiors.all_hollow() && (state.radiosity_depth == 0 || sample_volume_);
  if (rainbows_ && volume) r = with_rainbows(ray, hit.t, r);   // before media and fog, as POV-Ray's TraceRay
  if (media_ && volume) {
    if (!fog_) return with_media(ray, hit.t, hit.found(), state, r);
    r = with_media(ray, hit.t, hit.found(), state, r);
  }
  if (fog_ && volume) return with_fog(ray, hit.t, r);
  return r;
}

// A radiosity sample ray (radiosity.cpp GatherLight, trace.cpp TraceRay; study §4.4): traced as an ordinary ray
// from a fresh ticket — its own trace level, maximum level and ADC bailout for its whole tree, no interiors, no
// background transparency, flagged radiosity (no_radiosity objects are not there for it). At its first hit it
// compares the object's importance with its share i/(n−1) of the sample and is dropped, unshaded, below it; its
// hit distance counts either way.
radiosity::SampleRayResult Tracer::trace_sample(Vec3 origin, Vec3 direction, const radiosity::SampleRayParams& p) {
  assert(gatherer_ && p.level <= p.max_level && p.weight >= p.adc_bailout);
  ++counts_.secondary;
  const Ray ray{origin, direction, scene_.any_ray_flags ? ray_kind::radiosity : ray_kind::other};
  const Hit hit = scene_.accelerator.closest_hit(ray, tolerance::min_isect_depth, tolerance::bound_huge);
  const radiosity::RenderRadiosity& rad = *scene_.radiosity;
  radiosity::SampleRayResult out;
  const float own = hit.found() ? hit.surface.leaf->radiosity_importance : -1.0f;
  out.importance = own < 0 ? rad.default_importance : own;
  gatherer_->importance_found(out.importance);
  out.depth = hit.found() ? hit.t : HUGE_VAL;
  out.kept = !(out.importance < p.importance_queried);
  if (!out.kept) return out;
  struct TicketScope {   // the ticket's limits and the radiosity shadow caches, restored after the ray
    Tracer& t;
    int max_level;
    double adc_bailout, transmit_bailout;
    std::size_t shadow_base;
    ~TicketScope() {
      t.max_level_ = max_level;
      t.adc_bailout_ = adc_bailout;
      t.transmit_bailout_ = transmit_bailout;
      t.shadow_cache_base_ = shadow_base;
    }
  } scope{*this, max_level_, adc_bailout_, transmit_bailout_, shadow_cache_base_};
  max_level_ = p.max_level;
  adc_bailout_ = p.adc_bailout;
  transmit_bailout_ = quality_.refraction ? p.adc_bailout : HUGE_VAL;
  shadow_cache_base_ = 2 * scene_.lights.size();
  RayState state;
  state.alpha_background = false;
  state.radiosity_depth = p.depth;
  const Radiance r = hit.found() ? shade_hit(ray, hit.surface, p.level, p.weight, state) : background(direction, state);
  Radiance seen = r;
  if (rainbows_ && sample_volume_) seen = with_rainbows(ray, hit.t, seen);
  if (media_ && sample_volume_) seen = with_media(ray, hit.t, hit.found(), state, seen);
  out.colour = (fog_ && sample_volume_) ? with_fog(ray, hit.t, seen).colour : seen.colour;
  return out;
}

// The colour of a miss (pipeline §5, POV-Ray's ComputeSky): the sky_sphere's pigments, last written first, at the
// ray direction, each seen through those before it, then the background as one more layer. The background's filter
// and transmit count only where the ray may show them (camera rays with alpha output; never reflected rays).
Radiance Tracer::background(Vec3 direction, const RayState& state) const {
  const Vec3 p = scene_.sky_transformed ? scene_.sky_from_world.point(direction) : direction;
  if (scene_.language_version < 370) return legacy_background(p, state);
  Rgb col{0, 0, 0};
  Rgb filter{1, 1, 1};
  for (auto it = scene_.sky_pigments.rbegin(); it != scene_.sky_pigments.rend(); ++it) {
    const Colour c = evaluate_pigment(*it, p);
    col += mul(mul(Rgb{c.r, c.g, c.b} * (1.0 - c.f - c.t), filter), scene_.sky_emission);
    filter = mul(filter, pass_through(c));
  }
  Colour bg = scene_.background_colour;
  if (!state.alpha_background) bg.f = bg.t = 0;
  col += mul(Rgb{bg.r, bg.g, bg.b} * (1.0 - bg.f - bg.t), filter);
  filter = mul(filter, pass_through(bg));
  return {col, std::min(1.0, std::fabs(grey(filter)))};
}

// Scenes older than 3.7 composite the sky over the background by 3.6's rules, and with alpha output a camera ray's
// miss is fully transparent black.
Radiance Tracer::legacy_background(Vec3 p, const RayState& state) const {
  if (state.alpha_background) return {{0, 0, 0}, 1.0};
  const Colour& bg = scene_.background_colour;
  if (scene_.sky_pigments.empty()) return {{bg.r, bg.g, bg.b}, bg.t};
  Rgb col{0, 0, 0};
  Colour filter{1, 1, 1, 1, 1};
  double trans = 1.0;
  for (auto it = scene_.sky_pigments.rbegin(); it != scene_.sky_pigments.rend(); ++it) {
    const Colour c = evaluate_pigment(*it, p);
    col += Rgb{c.r, c.g, c.b} * (trans * (1.0 - c.f - c.t));
    filter = Colour{filter.r * c.r, filter.g * c.g, filter.b * c.b, filter.f * c.f, filter.t * c.t};
    trans = std::fabs(filter.f) + std::fabs(filter.t);
  }
  col = mul(col, scene_.sky_emission);
  const Rgb through{filter.r * filter.f + filter.t, filter.g * filter.f + filter.t, filter.b * filter.f + filter.t};
  return {col + mul(Rgb{bg.r, bg.g, bg.b}, through), bg.t * filter.t};
}

InteriorRef Tracer::interior_of(const SurfaceHit& hit) const {
  const Material& m = scene_.materials[hit.leaf->material];
  return InteriorRef{hit.leaf->object, &m.interior, m.media.get()};
}

double Tracer::relative_ior(const InteriorRef& self, const RayState& state) const {
  const InteriorList& in = state.interiors;
  const double ior = self.interior->ior;
  if (in.empty()) return ior;                        // entering from the atmosphere (ior 1)
  if (!in.contains(self)) return ior / in.back().interior->ior;   // entering a new object
  if (in.size() == 1) return 1.0 / ior;              // leaving into the atmosphere
  return in.back().interior->ior / ior;              // leaving into another object (POV-Ray's formula as is)
}

namespace {
bool is_zero(Rgb c) { return c.x == 0 && c.y == 0 && c.z == 0; }

}  // namespace

namespace {
Radiance mix(const Radiance& a, double wa, const Radiance& b, double wb) {
  return {a.colour * wa + b.colour * wb, a.transmit * wa + b.transmit * wb};
}

}  // namespace

// The material(s) shading a hit seen along `direction`: the object's interior_texture when the ray meets the surface
// from inside, i.e. the raw normal, turned by `inverse`, points along the ray (POV-Ray's ComputeTextureColour and
// ComputeShadowTexture; a mesh's triangle textures give way to it too, Mesh::Determine_Textures).
MaterialBlend Tracer::materials_facing(const SurfaceHit& hit, Vec3 point, Vec3 direction) const {
  const std::uint32_t inside = scene_.materials[hit.leaf->material].interior_material;
  if (inside == ~0u) [[likely]]
    return materials_at(hit, point);
  const double along = dot(surface_normal(hit, point), direction);
  if (hit.leaf->inverse ? along < 0.0 : along > 0.0) {
    MaterialBlend blend;
    blend.material[0] = inside;
    return blend;
  }
  return materials_at(hit, point);
}

Radiance Tracer::shade_hit(const Ray& ray, const SurfaceHit& hit, int level, double weight, const RayState& state) {
  // The shadow rays of this hit use the shadow-cache slot of its level; the rays it traces set their own.
  struct LevelScope {
    int& current;
    int outer;
    ~LevelScope() { current = outer; }
  } scope{shading_level_, shading_level_};
  shading_level_ = level;
  const Vec3 point = hit_point(ray, hit);
  const MaterialBlend blend = materials_facing(hit, point, ray.direction);
  bool uv = false;
  for (int k = 0; k < blend.count; ++k) uv = uv || scene_.materials[blend.material_of(k)].needs_uv;
  const TexturePoint at = texture_point(hit, point, uv, scene_.scale);
  if (blend.count == 1) return shade_material(ray, hit, scene_.materials[blend.material_of(0)], at, level, weight, state);
  // A mesh triangle with a texture_list: each texture shaded whole, the results blended by their weights; weights
  // below adc_bailout are skipped (POV-Ray's ComputeTextureColour).
  Radiance out;
  for (int k = 0; k < blend.count; ++k) {
    if (blend.weight_of(k) < adc_bailout_) continue;
    const Radiance r = shade_material(ray, hit, scene_.materials[blend.material_of(k)], at, level, weight, state);
    out.colour += r.colour * blend.weight_of(k);
    out.transmit += r.transmit * blend.weight_of(k);
  }
  return out;
}

Radiance Tracer::shade_material(const Ray& ray, const SurfaceHit& hit, const Material& material,
                                const TexturePoint& at, int level, double weight, const RayState& state) {
  const Vec3 point = hit_point(ray, hit);
  const Vec3 geometric = surface_normal(hit, point);
  // Every surface is two-sided: shade on the side the ray sees (§2 "Normal").
  const Vec3 raw_normal = dot(geometric, ray.direction) > 0 ? -geometric : geometric;
  const ShadingPoint sp{hit, point, raw_normal, warps_.size()};
  if (!material.needs_surface) [[likely]]
    return shade_texture(ray, sp, material.texture, material_point(material, at), level, weight, state);
  // slope and aoi read POV-Ray's PNormal: the normal facing the ray, at the scene's own scale.
  const ShadingSurface surface{point / scene_.scale, raw_normal, ray.direction};
  TexturePoint on_surface = material_point(material, at);
  on_surface.surface = &surface;
  return shade_texture(ray, sp, material.texture, on_surface, level, weight, state);
}

// A patterned texture shades the texture(s) its pattern picks at the pattern-space point, every one of them whole,
// and blends the results (POV-Ray's ComputeOneTextureColour); `average` weighs all of them, `uv_mapping` shades
// its one texture at the hit's <u, v, 0>. Layer normals below are taken through the pattern's transforms.
Radiance Tracer::shade_texture(const Ray& ray, const ShadingPoint& sp, const RenderTexture& texture,
                               const TexturePoint& at, int level, double weight, const RayState& state) {
  if (!texture.patterned()) return shade_layers(ray, sp, texture, at, level, weight, state);
  warps_.push_back(&texture);
  Radiance out;
  const RenderPigment& pattern = texture.pattern;
  if (pattern.pattern == PatternKind::uv_mapping) {
    out = shade_texture(ray, sp, texture.children.front(), at.at_uv(), level,
                        weight, state);
  } else {
    const TexturePoint p = at.moved(to_pattern_space(pattern, at.point));
    if (pattern.pattern == PatternKind::average) {
      double total = 0;
      for (const RenderTexture& c : texture.children) {
        out = mix(out, 1.0, shade_texture(ray, sp, c, p, level, weight, state), c.value);
        total += c.value;
      }
      out = mix(out, 1.0 / total, Radiance{}, 0.0);
    } else {
      const double value = texture_pattern_value(texture, p);
      const MapChoice m = choose_entries(texture.children, value);
      out = shade_texture(ray, sp, texture.children[m.cur], p, level, weight, state);
      if (m.prev != m.cur)
        out = mix(out, m.fraction, shade_texture(ray, sp, texture.children[m.prev], p, level, weight, state),
                  1.0 - m.fraction);
    }
  }
  warps_.pop_back();
  return out;
}

// A layer's normal: through the transforms of the patterned textures above (outermost first), bent by the layer's
// normal, and back (POV-Ray's Warp_Normal, Perturb_Normal, UnWarp_Normal in ComputeLightedTexture).
Vec3 Tracer::layer_normal(const RenderNormal& normal, const ShadingPoint& sp, const TexturePoint& at) const {
  Vec3 n = sp.raw_normal;
  for (std::size_t i = sp.warps_from; i < warps_.size(); ++i)
    if (warps_[i]->warps_normals) n = normalize(warps_[i]->world_from_pattern.normal_from_inverse(normalize(n)));
  n = perturb_normal(normal, n, at, scene_.wave_sources);
  for (std::size_t i = warps_.size(); i-- > sp.warps_from;)
    if (warps_[i]->warps_normals) n = normalize(warps_[i]->pattern_from_world.normal_from_inverse(normalize(n)));
  return n;
}

Radiance Tracer::shade_layers(const Ray& ray, const ShadingPoint& sp, const RenderTexture& texture,
                              const TexturePoint& at, int level, double weight, const RayState& state) {
  if (quality_.full_ambient) [[unlikely]] return unlit_layers(texture, at);
  // With radiosity, a separate instance of the layer loop, so that the loop without it is the one it always was.
  if (gatherer_) [[unlikely]] return shade_layers_as<true>(ray, sp, texture, at, level, weight, state);
  return shade_layers_as<false>(ray, sp, texture, at, level, weight, state);
}

template <bool Radiosity>
Radiance Tracer::shade_layers_as(const Ray& ray, const ShadingPoint& sp, const RenderTexture& texture,
                                 const TexturePoint& at, int level, double weight, const RayState& state) {
  const Vec3 point = sp.point;
  const Vec3 raw_normal = sp.raw_normal;
  const SurfaceHit& hit = sp.hit;
  const InteriorRef self = interior_of(hit);

  // Layers top first; each is weighted by what the layers above let through (§2 "Layers"). Their reflections are
  // computed here and traced after the transmitted ray, unfiltered by the layers above (§4).
  Radiance out;
  Rgb filter{1, 1, 1};
  double trans = 1.0;
  const std::size_t first_reflection = reflections_.size();
  // Radiosity: POV-Ray computes it for surfaces below recursion_limit (CheckRadiosityTraceLevel).
  [[maybe_unused]] AmbientSides ambient;
  [[maybe_unused]] const bool radiosity =
      Radiosity && state.radiosity_depth < static_cast<int>(scene_.radiosity->depths.size());
  Vec3 top_normal = raw_normal;   // the top layer's normal: refraction and TIR use it (§4)
  // Photons: gathered once for the hit, added to each layer's light unless the object ignores them (collect off),
  // which also keeps photon targets from darkening its shadows.
  PhotonGather photon_gather;
  const bool ignores_photons = !scene_.materials[hit.leaf->material].photons.collect;
  struct IgnoreScope {
    bool& current;
    bool outer;
    ~IgnoreScope() { current = outer; }
  } ignore_scope{lit_ignores_photons_, lit_ignores_photons_};
  lit_ignores_photons_ = ignores_photons;
  const bool gather_photons = photon_map_ && !ignores_photons && !state.pretrace && model_ == ShadingModel::povray;
  // What slope and aoi see as the normal (POV-Ray's PNormal): the raw one until a layer bends it, then that layer's
  // normal, for this layer and the ones below it.
  ShadingSurface surface;
  TexturePoint layer_at = at;
  if (at.surface) [[unlikely]] {
    surface = *at.surface;
    layer_at.surface = &surface;
  }
  for (const RenderLayer& layer : texture.layers) {
    if (trans <= adc_bailout_) break;
    // Each layer bends the raw normal (facing the ray) on its own (§2, POV-Ray's Perturb_Normal per layer).
    const bool bent = layer.normal && quality_.normals;
    const Vec3 normal = bent ? layer_normal(*layer.normal, sp, layer_at) : raw_normal;
    if (bent) surface.normal = normal;
    if (&layer == &texture.layers.front()) top_normal = normal;
    // Not found only off an image map used once: the layer then filters nothing.
    const auto [s, found] = sample_pigment(layer.pigment, layer_at);
    if (layer.reflects) {
      const double c = -dot(ray.direction, normal);
      const double ior = layer.finish.reflection_fresnel ? relative_ior(self, state) : 1.0;
      auto [amount, w] = reflectivity(layer.finish, c, ior, weight * trans);
      if (const double m = layer.finish.reflection_metallic; m != 0) {
        const double fade = metallic_fade(std::fabs(std::acos(std::clamp(c, -1.0, 1.0))) / (M_PI / 2));
        amount = mul(amount, Rgb{1, 1, 1} + (Rgb{s.r, s.g, s.b} - Rgb{1, 1, 1}) * (m * (1.0 - fade)));
      }
      reflections_.push_back(PendingReflection{amount, w, layer.reflection_exponent_inverse, normal, &layer.finish});
    }
    Rgb lit = model_ == ShadingModel::povray
                  ? lit_layer_povray<Radiosity>(layer, s, point, normal, ray.direction, state, sp.hit)
                  : lit_layer_textbook(layer, s, point, normal, ray.direction, state);
    if constexpr (Radiosity)
      if (radiosity) lit += radiosity_layer(layer, s, filter, sp, normal, weight, state, ambient);
    if (gather_photons) [[unlikely]] lit += photon_light(layer, s, sp, normal, ray.direction, state, photon_gather);
    out.colour += mul(lit, filter);
    if (found) {
      filter = mul(filter, pass_through(s));
      // conserve_energy: what the layer reflects is no longer transmitted (§2 "Layers").
      if (layer.reflects && layer.finish.conserve_energy) {
        const Rgb a = reflections_.back().amount;
        filter = mul(filter, Rgb{std::min(1.0, 1.0 - a.x), std::min(1.0, 1.0 - a.y), std::min(1.0, 1.0 - a.z)});
      }
    }
    trans = std::min(1.0, std::fabs(grey(filter)));
  }

  if (photon_gather.done) --photon_gather_depth_;
  const HitContext here{ray, sp, level, weight, state};
  bool total_internal_reflection = false;
  if (trans > transmit_bailout_) {
    const Transmission t = transmit(here, top_normal, filter, trans, texture.layers.front().finish);
    out.colour += t.colour;
    if (!t.total_internal_reflection) out.transmit = t.transmit;
    total_internal_reflection = t.total_internal_reflection;
  }

  // Reflections; after total internal reflection those sharing the top layer's normal are skipped (§4 TIR). Below
  // +Q8 none is traced (their amounts were still computed: conserve_energy used them above).
  const std::size_t traced_end = quality_.reflection ? reflections_.size() : first_reflection;
  for (std::size_t i = first_reflection; i < traced_end; ++i) {
    const PendingReflection r = reflections_[i];
    if (is_zero(r.amount)) continue;
    if (total_internal_reflection && r.normal == top_normal) continue;
    const Radiance seen = trace_reflection(here, r.normal, r.weight, r.finish);
    if (r.exponent != 1.0)
      out.colour += mul(r.amount, Rgb{std::pow(seen.colour.x, r.exponent), std::pow(seen.colour.y, r.exponent),
                                      std::pow(seen.colour.z, r.exponent)});
    else
      out.colour += mul(r.amount, seen.colour);
  }
  reflections_.resize(first_reflection);
  return out;
}

// POV-Ray's Q_FULL_AMBIENT (+Q0, +Q1): each layer in turn replaces the colour with its pigment's, unlit and opaque,
// while the layers above let light through; nothing is transmitted or reflected.
Radiance Tracer::unlit_layers(const RenderTexture& texture, const TexturePoint& at) const {
  Radiance out;
  Rgb filter{1, 1, 1};
  double trans = 1.0;
  for (const RenderLayer& layer : texture.layers) {
    if (trans <= adc_bailout_) break;
    const auto [s, found] = sample_pigment(layer.pigment, at);
    out.colour = Rgb{s.r, s.g, s.b};
    if (found) filter = mul(filter, pass_through(s));
    trans = std::min(1.0, std::fabs(grey(filter)));
  }
  return out;
}

// The mirror ray about the layer normal, corrected when it would go into the geometric surface (a perturbed
// normal can do that), traced one level deeper without background transparency (§4, §5).
Radiance Tracer::trace_reflection(const HitContext& at, Vec3 normal, double reflected_weight, const Finish* irid) {
  const Ray& ray = at.ray;
  ++counts_.secondary;
  RayState reflected = at.state;
  reflected.alpha_background = false;
  const Vec3 direction = mirror_direction(ray.direction, normal, at.sp.raw_normal);
  Radiance seen = trace(Ray{at.sp.point, direction, ray_kind::after_reflection(ray.kind)}, at.level + 1,
                        reflected_weight, reflected);
  // irid tints the reflected colour too (POV-Ray's ComputeReflection), with the reflected ray as the incoming light.
  if (irid && irid->irid > 0) [[unlikely]]
    seen.colour = mul(seen.colour, irid_factor(*irid, direction, ray.direction, normal, at.sp.point));
  return seen;
}

// Transmission (§4 "Transmission/refraction"): the relative ior comes from the interiors the ray is in.
Tracer::Transmission Tracer::transmit(const HitContext& at, Vec3 normal, Rgb filter, double trans,
                                      const Finish& top_finish) {
  const Ray& ray = at.ray;
  const SurfaceHit& hit = at.sp.hit;
  const Vec3 point = at.sp.point;
  const int level = at.level;
  const RayState& state = at.state;
  const InteriorRef self = interior_of(hit);
  const Interior& interior = *self.interior;
  const double next_weight =
      at.weight * max_channel(Rgb{std::fabs(filter.x), std::fabs(filter.y), std::fabs(filter.z)});
  RayState next = state;
  const double eta = cross_interior(next.interiors, self);   // n_from / n_to

  // Fade of the light that travelled inside this interior, from the ray's origin to here (§4 "interior fade").
  Rgb attenuation{interior.refraction, interior.refraction, interior.refraction};
  if (state.interiors.contains(self) && std::fabs(interior.fade_distance) > tolerance::epsilon) {
    const Rgb fc = rgb_of(interior.fade_colour);
    const double depth = hit.t / interior.fade_distance;
    if (interior.fade_power >= 1000) {
      attenuation = mul(attenuation, Rgb{std::exp(-(1 - fc.x) * depth), std::exp(-(1 - fc.y) * depth),
                                         std::exp(-(1 - fc.z) * depth)});
    } else {
      const double a = 1.0 + std::pow(depth, interior.fade_power);
      attenuation = mul(attenuation, fc + (Rgb{1, 1, 1} - fc) / a);
    }
  }

  ++counts_.secondary;
  Radiance behind;
  if (std::fabs(eta - 1.0) < tolerance::epsilon) {
    // An ior-1 surface continues the ray without using up a trace level.
    // POV-Ray flags it as refracted too (ComputeRefraction sets the flags before this case). Its TraceRay tests
    // the level the continued ray shares with its parent against the maximum before anything else, so at the
    // deepest level the continued ray sees black (trace() allows an ordinary child one level deeper).
    if (level < max_level_)
      behind = trace(Ray{point, ray.direction, ray_kind::after_refraction(ray.kind)}, level, next_weight, next);
  } else {
    const std::optional<Vec3> refracted = refracted_direction(ray.direction, normal, eta);
    if (!refracted) {
      // Total internal reflection: the mirror ray (top layer's normal), not filtered by the layers (§4 TIR).
      // POV-Ray's TraceRefractionRay reflects with the top layer's finish: its irid tints the reflection too.
      const Radiance reflected = trace_reflection(at, normal, next_weight, &top_finish);
      return {mul(attenuation, reflected.colour), 0.0, true};
    }
    behind = trace(Ray{point, *refracted, ray_kind::after_refraction(ray.kind)}, level + 1, next_weight, next);
  }
  return {mul(mul(attenuation, filter), behind.colour), grey(attenuation) * behind.transmit * trans, false};
}

std::optional<Tracer::LightRay> Tracer::light_at(const RenderLight& l, Vec3 point) const {
  if (l.light.cylinder) return cylinder_light_at(l, point);
  Vec3 to_light;
  double distance;
  if (l.light.parallel) {
    // Parallel light (§3): fixed direction; distance is the projection onto it, so only objects between the
    // hit and the plane through `location` cast shadows.
    to_light = l.parallel_direction;
    distance = dot(l.light.location - point, to_light);
  } else {
    const Vec3 v = l.light.location - point;
    distance = length(v);
    to_light = v / distance;
  }
  Rgb colour = l.colour;
  if (l.light.spotlight) {
    const double cos_angle = -dot(to_light, l.spot_axis);
    if (cos_angle <= 0) return std::nullopt;
    double a = l.light.tightness != 0 ? power(cos_angle, l.light.tightness) : 1.0;
    if (cos_angle < l.cos_radius) a *= smoothstep(l.cos_falloff, l.cos_radius, cos_angle);
    colour *= a;
  }
  if (l.fades) colour *= 2.0 / (1.0 + power(distance / l.light.fade_distance, l.light.fade_power));
  if (near_zero(colour)) return std::nullopt;
  return LightRay{colour, to_light, distance};
}

// A cylindrical light (POV-Ray's Attenuate_Light and ComputeOneWhiteLightRay): parallel beams along point_at →
// location, full inside `radius` of the axis, fading to 0 at `falloff` by the smooth step of 1 − d/falloff, raised
// to `tightness`; nothing behind the light's plane. The distance for fade and shadows is along the beam.
std::optional<Tracer::LightRay> Tracer::cylinder_light_at(const RenderLight& l, Vec3 point) const {
  const Light& light = l.light;
  const Vec3 to_light = -l.spot_axis;
  const double distance = dot(light.location - point, to_light);
  const Vec3 from_centre = point - light.location;
  const double along = dot(from_centre, l.spot_axis);
  if (!(along > 0)) return std::nullopt;
  const double off_axis = length(from_centre - l.spot_axis * along);
  if (!(off_axis < light.falloff)) return std::nullopt;
  const double d = 1.0 - off_axis / light.falloff;
  double a = power(d, light.tightness);
  if (light.radius > 0 && off_axis > light.radius) a *= smoothstep(0.0, 1.0 - light.radius / light.falloff, d);
  Rgb colour = l.colour * a;
  if (l.fades) colour *= 2.0 / (1.0 + power(distance / light.fade_distance, light.fade_power));
  if (near_zero(colour)) return std::nullopt;
  return LightRay{colour, to_light, distance};
}

// A transparent object filters at every surface crossing, through all its layers (§3); a texture_list triangle by the
// weighted sum of its textures' filters (an opaque texture among them passes nothing); a patterned texture by the
// filters of the textures its pattern picks, blended as their colours would be.
Rgb Tracer::filter_through(const SurfaceHit& hit, Vec3 at, Vec3 direction) {
  const MaterialBlend blend = materials_facing(hit, at, direction);
  if (blend.count == 1 && scene_.materials[blend.material_of(0)].opaque) return {0, 0, 0};
  bool uv = false;
  for (int k = 0; k < blend.count; ++k) uv = uv || scene_.materials[blend.material_of(k)].needs_uv;
  TexturePoint point = texture_point(hit, at, uv, scene_.scale);
  ShadingSurface surface;
  Rgb through{0, 0, 0};
  for (int k = 0; k < blend.count; ++k) {
    const Material& m = scene_.materials[blend.material_of(k)];
    if (m.opaque) continue;
    if (m.needs_surface && !point.surface) {   // slope, aoi: the normal facing the shadow ray (trace.cpp)
      const Vec3 geometric = surface_normal(hit, at);
      surface = {at / scene_.scale, dot(geometric, direction) > 0 ? -geometric : geometric, direction};
      point.surface = &surface;
    }
    if (m.interior.caustics != 0.0) {
      const Vec3 geometric = surface_normal(hit, at);
      std::vector<const RenderTexture*> path;
      const CausticsAt c{dot(geometric, direction) > 0 ? -geometric : geometric, direction, m.interior.caustics, &path};
      through += texture_filter(m.texture, material_point(m, point), &c) * blend.weight_of(k);
      continue;
    }
    through += texture_filter(m.texture, material_point(m, point)) * blend.weight_of(k);
  }
  return through;
}

Rgb Tracer::texture_filter(const RenderTexture& texture, const TexturePoint& at, const CausticsAt* caustics) const {
  if (!texture.patterned()) {
    Rgb layers{1, 1, 1};
    for (const RenderLayer& layer : texture.layers) {
      const PigmentSample s = sample_pigment(layer.pigment, at);
      if (s.found) layers = mul(layers, pass_through(s.colour));
      if (caustics) layers *= caustics_factor(layer, *caustics, at);
    }
    return layers;
  }
  struct PathScope {   // the patterned textures passed on the way down, for the caustics' layer normals
    const CausticsAt* c;
    explicit PathScope(const CausticsAt* c_, const RenderTexture* t) : c(c_) {
      if (c) c->path->push_back(t);
    }
    ~PathScope() {
      if (c) c->path->pop_back();
    }
  } scope(caustics, &texture);
  const RenderPigment& pattern = texture.pattern;
  if (pattern.pattern == PatternKind::uv_mapping)
    return texture_filter(texture.children.front(), at.at_uv(), caustics);
  const TexturePoint p = at.moved(to_pattern_space(pattern, at.point));
  if (pattern.pattern == PatternKind::average) {
    Rgb sum{0, 0, 0};
    double total = 0;
    for (const RenderTexture& c : texture.children) {
      sum += texture_filter(c, p, caustics) * c.value;
      total += c.value;
    }
    return sum / total;
  }
  const double value = texture_pattern_value(texture, p);
  const MapChoice m = choose_entries(texture.children, value);
  const Rgb cur = texture_filter(texture.children[m.cur], p, caustics);
  if (m.prev == m.cur) return cur;
  return cur * m.fraction + texture_filter(texture.children[m.prev], p, caustics) * (1.0 - m.fraction);
}

// POV-Ray's fake caustics (ComputeShadowTexture): each layer's light through the surface is scaled by
// 1 + |N·L|^caustics, N the layer's normal as shading perturbs it (taken through the patterned textures' warps), L
// the shadow ray's direction.
double Tracer::caustics_factor(const RenderLayer& layer, const CausticsAt& c, const TexturePoint& at) const {
  Vec3 n = c.raw_normal;
  if (layer.normal && quality_.normals) {
    const auto& path = *c.path;
    for (const RenderTexture* t : path)
      if (t->warps_normals) n = normalize(t->world_from_pattern.normal_from_inverse(normalize(n)));
    n = perturb_normal(*layer.normal, n, at, scene_.wave_sources);
    for (auto t = path.rbegin(); t != path.rend(); ++t)
      if ((*t)->warps_normals) n = normalize((*t)->pattern_from_world.normal_from_inverse(normalize(n)));
  }
  return 1.0 + std::pow(std::fabs(dot(n, c.direction)), c.exponent);
}

// Shadow rays as POV-Ray traces them (trace.cpp TracePointLightShadowRay), see povray_shadow_walk. Hits count only
// with 1e-3 < t < distance − 1e-3 (§3, §8 SHADOW_TOLERANCE), except for the object in the shadow cache.
// projected_through (TracePointLightShadowRay): the light reaches the point only along rays that meet the object
// before the light; then only what lies nearer than that crossing, less SMALL_TOLERANCE, casts a shadow, and a fill
// light (shadowless) casts none. Each sample of an area light is tested so.
Rgb Tracer::shadow_filter(const RenderLight& l, Vec3 point, Vec3 to_light, double distance,
                          const RayState& state) {
  const Ray ray{point, to_light};
  double reach = distance;   // occluders count short of this depth
  if (l.projected_through) {
    const std::optional<TracedHit> through = l.projected_through->trace(point, to_light);
    if (!through) return {0, 0, 0};
    const double depth = dot(through->point - point, to_light);
    if (!(depth - distance < 0.0)) return {0, 0, 0};
    reach = std::fabs(depth) - tolerance::shadow;
    if (l.light.shadowless) return shadow_atmosphere(l, ray, 0.0, distance, {1, 1, 1}, state.interiors.all_hollow(), false);
  }
  if (scene_.specialisation.no_shadow_rays)
    return shadow_atmosphere(l, ray, 0.0, distance, {1, 1, 1}, state.interiors.all_hollow(), false);
  ++counts_.shadow;
  return povray_shadow_walk(l, ray, distance, reach, state);
}

bool Tracer::opaque_at(const SurfaceHit& hit) const {
  const Primitive& p = *hit.leaf;
  if (p.type == ShapeType::blob) {   // POV-Ray's Test_Blob_Opacity: its texture and every component's opaque
    if (const std::uint32_t n = shapes::blob_texture_count(p)) {
      if (!scene_.materials[p.material].opaque) return false;
      for (std::uint32_t k = 0; k < n; ++k)
        if (!scene_.materials[p.element_materials + k].opaque) return false;
      return true;
    }
  }
  if (p.type == ShapeType::mesh) {
    const MaterialBlend blend = materials_at(hit, Vec3{});   // a triangle's textures: its weights need no point
    return blend.count == 1 && scene_.materials[blend.material_of(0)].opaque;
  }
  return scene_.materials[p.material].opaque;
}

namespace {
constexpr std::uint32_t kNoOccluder = ~0u;
}  // namespace

std::uint32_t& Tracer::shadow_cache_slot(const RenderLight& l) {
  if (shadow_cache_.empty()) shadow_cache_.assign((gatherer_ ? 4 : 2) * scene_.lights.size(), kNoOccluder);
  const auto light = static_cast<std::size_t>(&l - scene_.lights.data());
  return shadow_cache_[shadow_cache_base_ + 2 * light + (shading_level_ == 1 ? 0 : 1)];
}

// POV-Ray tests the cached object with FindIntersection(object, …, light distance): any hit from MIN_ISECT_DEPTH
// up to the light itself, with neither SHADOW_TOLERANCE limit of the ordinary walk.
bool Tracer::cached_occluder_blocks(std::uint32_t primitive, const Ray& ray, double distance) const {
  const std::optional<SurfaceHit> hit =
      nearest_hit(scene_.accelerator.primitives()[primitive], ray, tolerance::min_isect_depth, distance);
  return hit && opaque_at(*hit);
}

// POV-Ray's shadow ray exactly (trace.cpp TracePointLightShadowRay): first the object in the shadow cache; then
// from crossing to crossing, each more than SMALL_TOLERANCE beyond the last one counted (so two surfaces closer
// than 1e-3 along the ray filter once) and short of the light by more than SHADOW_TOLERANCE, until an opaque one.
// That one is cached when it is the first crossing counted. The cache is what shadows a point from an object
// nearer than SHADOW_TOLERANCE (contact shadows, the cells of a height field): POV-Ray tests the cached object
// from MIN_ISECT_DEPTH, so its images show it (prim_height_field, prim_prism, bump_map matched POV-Ray only to
// 60-71 dB without it, 115-121 dB with it). With fading interiors the shadow ray also tracks the interiors it is
// in (it starts in those of the ray that reached the point), and light fades over each stretch inside one (§3).
namespace {
// A julia_fractal outside CSG reports only the first surface its march meets (POV-Ray's Fractal::All_Intersections
// stops there), and a blob outside CSG only the crossings of the first stretch of its field that has any (Blob::
// All_Intersections stops there), so the surfaces beyond are found only by the ray POV-Ray's shadow walk starts
// from that hit.
bool reports_first_hit_only(const Primitive& p) {
  return (p.type == ShapeType::julia_fractal || p.type == ShapeType::blob) && !p.csg_child;
}
}  // namespace

// POV-Ray moves its shadow ray to each crossing it counts and looks again from there: for an object that reports only
// its first hit, the next crossing of the same object is found from the one at depth `at` and joins the sorted list
// after position k, if it lies before `last`, the farthest depth at which a crossing counts.
template <class Crossings>
void Tracer::add_next_crossing_of(std::uint32_t primitive, const Ray& ray, double at, double last,
                                  Crossings& crossings, std::size_t k) const {
  const Ray from_here{hit_point(ray, crossings[k].hit), ray.direction, ray.kind};
  const std::optional<SurfaceHit> next = nearest_hit(scene_.accelerator.primitives()[primitive], from_here,
                                                     tolerance::shadow, last - at);
  if (!next) return;
  auto crossing = crossings[k];
  crossing.hit = *next;
  crossing.hit.t = at + next->t;
  auto place = crossings.begin() + static_cast<std::ptrdiff_t>(k) + 1;
  while (place != crossings.end() && place->hit.t <= crossing.hit.t) ++place;
  crossings.insert(place, crossing);
}

Rgb Tracer::povray_shadow_walk(const RenderLight& l, const Ray& ray, double distance, double reach,
                               const RayState& state) {
  // POV-Ray caches no occluder for a light_group's lights.
  std::uint32_t uncached = kNoOccluder;
  std::uint32_t& cached = l.light.group < 0 ? shadow_cache_slot(l) : uncached;
  if (cached != kNoOccluder && cached_occluder_blocks(cached, ray, reach)) return {0, 0, 0};
  const double last = std::min(distance - tolerance::shadow, reach);   // the farthest crossing that counts
  if (scene_.specialisation.nearest_shadow_first) {
    // The walk below starts at the nearest crossing and ends there when it is opaque (ties between primitives go
    // to the lower index in both).
    const Hit first = scene_.accelerator.closest_shadow_hit(ray, tolerance::shadow, last);
    if (!first.found())
      return shadow_atmosphere(l, ray, 0.0, distance, {1, 1, 1}, state.interiors.all_hollow(), false);
    if (opaque_at(first.surface)) {
      cached = first.primitive;
      return {0, 0, 0};
    }
  }
  struct Crossing {
    SurfaceHit hit;
    std::uint32_t primitive;
  };
  thread_local std::vector<Crossing> crossings;
  crossings.clear();
  scene_.accelerator.for_each_shadow_hit(ray, tolerance::shadow, last,
                                         [&](std::uint32_t i, const SurfaceHit& hit) { crossings.push_back({hit, i}); });
  std::stable_sort(crossings.begin(), crossings.end(), [](const Crossing& a, const Crossing& b) {
    return a.hit.t < b.hit.t || (a.hit.t == b.hit.t && a.primitive < b.primitive);
  });
  Rgb f{1, 1, 1};
  InteriorList in;
  const bool track = scene_.any_shadow_fade || scene_.any_interior_media || shadow_atmosphere_;
  if (track) in = state.interiors;
  double previous = 0;
  for (std::size_t k = 0; k < crossings.size(); ++k) {
    const Crossing c = crossings[k];
    if (previous > 0 && c.hit.t - previous <= tolerance::shadow) continue;
    if (reports_first_hit_only(scene_.accelerator.primitives()[c.primitive]))
      add_next_crossing_of(c.primitive, ray, c.hit.t, last, crossings, k);
    if (opaque_at(c.hit)) {
      if (previous == 0) cached = c.primitive;
      return {0, 0, 0};
    }
    if (photon_map_ && photons_replace_shadow(l, c.hit)) return {0, 0, 0};
    Rgb through = filter_through(c.hit, hit_point(ray, c.hit), ray.direction);
    // The media of the interiors crossed since the last surface dim the light the surface lets through (POV-Ray's
    // ComputeShadowColour), as the atmosphere does for lights with media_attenuation (ComputeShadowMedia).
    if (media_ && scene_.any_interior_media && in.any_media() && in.all_hollow() && !all_below(through, tolerance::epsilon))
      through = mul(through, shadow_interior_media(ray, previous, c.hit.t, in));
    f = mul(f, through);
    f = shadow_atmosphere(l, ray, previous, c.hit.t, f, in.all_hollow(), true);
    if (track) {
      const InteriorRef self = interior_of(c.hit);
      if (in.contains(self)) f = mul(f, shadow_fade(*self.interior, c.hit.t - previous));
      if (in.empty() || !in.remove(self)) in.append(self);
    }
    previous = c.hit.t;
    if (all_below(f, tolerance::epsilon)) break;
  }
  if (distance - previous > tolerance::shadow)
    f = shadow_atmosphere(l, ray, previous, distance, f, in.all_hollow(), false);
  return f;
}

Rgb Tracer::shadowed_light(const RenderLight& l, Vec3 point, Vec3 to_light, double distance, Rgb colour,
                           const RayState& state) {
  if (!quality_.shadows) return colour;   // below +Q4 (POV-Ray traces no shadow ray then)
  // Radiosity sample rays treat area lights as point lights (POV-Ray clears Q_AREA_LIGHT for them, study §1.1).
  if (l.light.area && quality_.area_lights && state.radiosity_depth == 0) return area_light_shadow(l, point, to_light, colour, state);
  return mul(colour, shadow_filter(l, point, to_light, distance, state));
}

// What one light of colour `lc` from direction `to_light` (c = N·L) adds to a layer (POV-Ray's ComputeDiffuseColour,
// ComputePhongColour and ComputeSpecularColour): diffuse with brilliance, or diffuse_back from behind; highlights
// tinted by metallic. The lights' loop and the photons' gather (photons/photon_gather.cpp) both use it.
// irid (POV-Ray's ComputeIridColour): a film of the finish's thickness, made uneven by 5 octaves of the scene's
// turbulence at the point when irid's turbulence is set, shifts the phase of each primary by
// 2π·thickness·(|N·L| + |N·E|) over its wavelength; the light is scaled by 1 + irid·cos(phase / wavelength).
Rgb Tracer::irid_factor(const Finish& fin, Vec3 incoming, Vec3 view, Vec3 normal, Vec3 point) const {
  double thickness = fin.irid_thickness;
  if (fin.irid_turbulence != 0) {
    Turbulence t;
    t.octaves = 5;
    t.omega = 0.5f;
    t.lambda = 2.0f;
    const double noise = 2.0 * turbulence(point / scene_.scale, t, scene_.noise_generator) - 1.0;
    thickness *= 1.0 + noise * fin.irid_turbulence;
  }
  const Colour& wl = scene_.settings.irid_wavelength;
  const double phase = 2.0 * M_PI * thickness * (std::fabs(dot(normal, incoming)) + std::fabs(dot(normal, view)));
  return {1.0 + fin.irid * std::cos(phase / wl.r), 1.0 + fin.irid * std::cos(phase / wl.g),
          1.0 + fin.irid * std::cos(phase / wl.b)};
}

// double_illuminate: a light behind the surface is no different (POV-Ray skips its Cos_Shadow_Angle test), and the
// diffuse term takes |N·L| as it always does.
Rgb Tracer::one_light(const RenderLayer& layer, Rgb pigment, double att, Vec3 point, Vec3 normal, Vec3 view, Rgb lc,
                      Vec3 to_light, double c, double speckle, bool highlights, bool double_illuminate) const {
  const Finish& fin = layer.finish;
  const auto with_irid = [&](Rgb light) {
    return fin.irid > 0 ? mul(light, irid_factor(fin, to_light, view, normal, point)) : light;
  };
  if (c < tolerance::epsilon && !double_illuminate) {   // behind the surface: only diffuse_back
    if (fin.diffuse_back > 0)
      return with_irid(mul(pigment, lc) * (fin.diffuse_back * att * std::pow(std::fabs(c), fin.brilliance) - speckle));
    return {};
  }
  Rgb out;
  const double cos_in = std::fabs(c);
  if (fin.diffuse > 0)
    out += mul(pigment, lc) *
           (fin.diffuse * att * (fin.brilliance == 1.0 ? cos_in : std::pow(cos_in, fin.brilliance)) - speckle);
  if (!highlights) return with_irid(out);
  Rgb highlight = lc;
  if (fin.metallic != 0) {
    const double fade = metallic_fade(std::acos(std::clamp(c, -1.0, 1.0)) / (M_PI / 2));
    highlight = mul(lc, Rgb{1, 1, 1} + (pigment - Rgb{1, 1, 1}) * (fin.metallic * (1.0 - fade)));
  }
  if (fin.phong != 0) {
    const Vec3 mirrored = view - normal * (2.0 * dot(view, normal));
    const double p = dot(mirrored, to_light);
    if (p > 0 && !(fin.phong_size >= kPhongCutoffSize && p <= kPhongCutoff))
      out += highlight * (fin.phong * std::pow(p, fin.phong_size));
  }
  if (fin.specular != 0) {
    const Vec3 half = (to_light - view) * 0.5;
    const double h = dot(normal, half) / length(half);
    if (h > 0) out += highlight * (fin.specular * std::pow(h, layer.specular_exponent));
  }
  return with_irid(out);
}

// POV-Ray's finish model for one layer (§2): ambient and emission scaled by opacity; per light, diffuse with
// brilliance, Phong and Blinn highlights (not scaled by opacity), metallic tint, back-side diffuse.
template <bool Radiosity>
Rgb Tracer::lit_layer_povray(const RenderLayer& layer, const Colour& s, Vec3 point, Vec3 normal, Vec3 view,
                             const RayState& state, const SurfaceHit& hit) {
  const bool double_illuminate = hit.leaf->double_illuminate;
  const Finish& fin = layer.finish;
  const Rgb pigment{s.r, s.g, s.b};
  const double att = scene_.language_version >= 370 ? 1.0 - s.f - s.t
                                                     : 1.0 - (s.f * std::max({s.r, s.g, s.b}) + s.t);
  Rgb out = mul(pigment * att, mul(rgb_of(fin.ambient), rgb_of(scene_.settings.ambient_light)) + rgb_of(fin.emission));
  // POV-Ray's light loop runs only for a finish with diffuse, diffuse_back, phong or specular (trace.cpp
  // ComputeDiffuseLight); skipping it is its behaviour, not a shortcut: its shadow rays would move the shadow cache.
  if (fin.diffuse == 0 && fin.diffuse_back == 0 && !layer.has_highlights) return out;
  // A pretrace ray's colour is thrown away: only its radiosity queries count, and lights play no part in them.
  if constexpr (Radiosity)
    if (state.pretrace) return out;
  // No light gives highlights to a radiosity sample ray's tree (trace.cpp: "NK rad").
  bool highlights = layer.has_highlights;
  if constexpr (Radiosity) highlights = highlights && state.radiosity_depth == 0;

  // The scene's lights, unless the object is in a light_group without global_lights, then its groups' lights, innermost
  // group first (POV-Ray's ComputeDiffuseLight: the global list, then the object's LLights).
  const Material& lit = scene_.materials[hit.leaf->material];
  const auto one = [&](std::size_t li) {
    const RenderLight& l = scene_.lights[li];
    const std::optional<LightRay> seen = light_at(l, point);
    if (!seen) return;
    auto [lc, to_light, distance] = *seen;
    const double c = dot(normal, to_light);
    // crand: POV-Ray lowers each diffuse term by a uniform random amount in [0, crand] drawn from a per-thread
    // sequence (its order depends on threads and blocks); ours is a hash of the point and the light, so the speckle
    // has the same distribution and the same image comes out whatever the threads.
    const double speckle = fin.crand > 0 ? fin.crand * speckle_random(point, li) : 0.0;
    const bool behind = c < tolerance::epsilon && !double_illuminate;
    if (behind && fin.diffuse_back == 0) return;   // a light behind the surface gives nothing at all
    if (!l.light.shadowless || l.projected_through) {   // a fill light is tested only for projected_through
      lc = shadowed_light(l, point, to_light, distance, lc, state);
      if (near_zero(lc)) return;
    }
    out += one_light(layer, pigment, att, point, normal, view, lc, to_light, c, speckle,
                     highlights && !l.light.shadowless, double_illuminate);   // fill lights give no highlights
  };
  if (lit.global_lights)
    for (std::size_t li = 0; li < scene_.lights.size(); ++li)
      if (scene_.lights[li].light.group < 0) one(li);
  for (const int group : lit.light_groups)
    for (std::size_t li = 0; li < scene_.lights.size(); ++li)
      if (scene_.lights[li].light.group == group) one(li);
  return out;
}

// The radiosity term of one layer (trace.cpp ComputeLightedTexture, study §1.1): A is asked for once per side and
// textured hit, by the first layer whose largest possible contribution grey(filter·S)·att·diffuse_raw exceeds the
// ADC bailout, with the ray weight times that contribution; layers before it add nothing, layers after it reuse it.
// The back side (diffuse_back ≠ 0) asks with both normals negated.
Rgb Tracer::radiosity_layer(const RenderLayer& layer, const Colour& s, Rgb filter, const ShadingPoint& sp, Vec3 normal,
                            double weight, const RayState& state, AmbientSides& sides) {
  const Finish& fin = layer.finish;
  const Rgb pigment{s.r, s.g, s.b};
  const double att = scene_.language_version >= 370 ? 1.0 - s.f - s.t
                                                     : 1.0 - (s.f * std::max({s.r, s.g, s.b}) + s.t);
  const double seen = grey(mul(filter, pigment)) * att;
  auto query = [&](bool back, double diffuse) {
    const Vec3 raw = back ? -sp.raw_normal : sp.raw_normal;
    const Vec3 bent = back ? -normal : normal;
    return gatherer_->ambient({sp.point, raw, bent, weight * seen * diffuse, state.radiosity_depth, max_level_}, *this);
  };
  // A side not computed yet adds nothing (POV-Ray's ambCol is still black then).
  auto store = [](double* slot, Rgb v) { slot[0] = v.x, slot[1] = v.y, slot[2] = v.z; };
  if (!sides.front_done && seen * fin.diffuse_raw > adc_bailout_) {
    store(sides.front, query(false, fin.diffuse_raw));
    sides.front_done = true;
  }
  Rgb out;
  if (sides.front_done)
    out = mul(pigment, Rgb{sides.front[0], sides.front[1], sides.front[2]}) * (att * fin.diffuse_raw);
  if (fin.diffuse_back != 0) {
    if (!sides.back_done && seen * fin.diffuse_back_raw > adc_bailout_) {
      store(sides.back, query(true, fin.diffuse_back_raw));
      sides.back_done = true;
    }
    if (sides.back_done)
      out += mul(pigment, Rgb{sides.back[0], sides.back[1], sides.back[2]}) * (att * fin.diffuse_back_raw);
  }
  return out;
}

// The seed chapter's direct illumination (../shared/seed/): ka·La·S + Σ kd(N·L)Ld·S + ks(R·E)^n and
// ks(N·H)^n tinted by (1−p)S + p, negative terms dropped. POV-Ray's finish maps onto ka, kd, ks, n, p as the
// README states; shadows use the same test as POV-Ray mode.
Rgb Tracer::lit_layer_textbook(const RenderLayer& layer, const Colour& s, Vec3 point, Vec3 normal, Vec3 view,
                               const RayState& state) {
  const Finish& fin = layer.finish;
  const Rgb pigment{s.r, s.g, s.b};
  Rgb out = mul(mul(rgb_of(scene_.settings.ambient_light), rgb_of(fin.ambient)), pigment);
  const double p = 1.0 - fin.metallic;
  const Rgb plastic = pigment * (1.0 - p) + Rgb{p, p, p};
  const Vec3 eye = -view;
  for (const RenderLight& l : scene_.lights) {
    const std::optional<LightRay> seen = light_at(l, point);
    if (!seen) continue;
    auto [lc, to_light, distance] = *seen;
    if (!l.light.shadowless || l.projected_through) {
      lc = shadowed_light(l, point, to_light, distance, lc, state);
      if (near_zero(lc)) continue;
    }
    const double n_dot_l = dot(normal, to_light);
    if (n_dot_l > 0) out += mul(lc, pigment) * (fin.diffuse * n_dot_l);
    if (fin.phong != 0) {
      const Vec3 r = normal * (2.0 * n_dot_l) - to_light;
      const double r_dot_e = dot(r, eye);
      if (r_dot_e > 0) out += mul(lc, plastic) * (fin.phong * std::pow(r_dot_e, fin.phong_size));
    }
    if (fin.specular != 0) {
      const Vec3 h = normalize(eye + to_light);
      const double n_dot_h = dot(normal, h);
      if (n_dot_h > 0) out += mul(lc, plastic) * (fin.specular * std::pow(n_dot_h, layer.specular_exponent));
    }
  }
  return out;
}

}  // namespace povtrace::render
