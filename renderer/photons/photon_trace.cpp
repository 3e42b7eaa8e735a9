// The photon pass's tracing (POV-Ray 3.7's PhotonTrace::TraceRay and ComputeLightedTexture, lighting/photons.cpp;
// docs/issue20-photons.md §2), written anew. A photon carries light energy; at a surface it is stored (after its
// first bounce, on objects that collect photons), then goes on as the reflections and refractions of the surface's
// layers allow, each taking its share of the energy.
#include <cmath>

#include "renderer/shading_helpers.hpp"
#include "renderer/tracer.hpp"
#include "renderer/pattern/render_texture.hpp"

namespace povtrace::render {

namespace {
bool is_black(Rgb c) { return c.x == 0 && c.y == 0 && c.z == 0; }

// Whether the object's and the light's flags let the photon refract (reflect): one of them `on` and the other not
// `off`.
bool allowed(const std::optional<bool>& object, const std::optional<bool>& light) {
  return (object == true && light != false) || (object != false && light == true);
}
}  // namespace

void Tracer::shoot_photon(const Ray& ray, Rgb colour, const std::vector<InteriorRef>& interiors, PhotonShot& shot,
                          double depth) {
  RayState state;
  state.alpha_background = false;
  for (const InteriorRef& r : interiors) state.interiors.append(r);
  shot.depth = depth;
  shot.pass_prev = true;
  shot.pass_this = false;
  photon_trace(ray, colour, 0, 1.0, state, shot);
}

// `level` is the trace level of the ray's origin (0 at the light). The first surface a photon meets, and any surface
// after a pass_through object, must be the target or let it pass: anything else ends the photon there.
void Tracer::photon_trace(const Ray& ray, Rgb colour, int level, double weight, const RayState& state,
                          PhotonShot& shot) {
  // POV-Ray passes ray weights as single-precision floats (COLC): a reflected weight of 0.1 · 0.1 is below an
  // adc_bailout of 0.01 there, as it is here once rounded the same way.
  weight = static_cast<float>(weight);
  if (level >= photon_max_level_ || weight < photon_adc_) return;
  const int here = level + 1;
  const Hit hit = scene_.accelerator.closest_hit(ray, tolerance::min_isect_depth, tolerance::bound_huge);
  if (!hit.found()) return;
  const bool outer_prev = shot.pass_prev;
  shot.pass_prev = shot.pass_this;
  shot.pass_this = false;
  const auto restore = [&] {
    shot.pass_this = shot.pass_prev;
    shot.pass_prev = outer_prev;
  };
  if (here == 1 || shot.pass_prev) {
    const Material& m = scene_.materials[hit.surface.leaf->material];
    const ObjectPhotons& f = m.photons;
    const bool the_target = m.photon_target == shot.target;
    if (the_target) {
      shot.hit_target = true;
    } else if (f.pass_through) {
      shot.pass_this = true;
    } else {
      restore();
      return;
    }
  }
  photon_surface(ray, hit.surface, colour, here, weight, state, shot);
  restore();
}

// POV-Ray's ComputeTextureColour in its photon pass: a texture_list triangle's textures each take their weight's
// share of the photon.
void Tracer::photon_surface(const Ray& ray, const SurfaceHit& hit, Rgb colour, int level, double weight,
                            const RayState& state, PhotonShot& shot) {
  const Vec3 point = hit_point(ray, hit);
  const MaterialBlend blend = materials_facing(hit, point, ray.direction);
  bool uv = false;
  for (int k = 0; k < blend.count; ++k) uv = uv || scene_.materials[blend.material_of(k)].needs_uv;
  TexturePoint at = texture_point(hit, point, uv, scene_.scale);
  const Vec3 geometric = surface_normal(hit, point);
  const Vec3 raw_normal = dot(geometric, ray.direction) > 0 ? -geometric : geometric;
  const ShadingSurface surface{point / scene_.scale, raw_normal, ray.direction};   // slope, aoi
  at.surface = &surface;
  const ShadingPoint sp{hit, point, raw_normal, warps_.size()};
  const PhotonHit here{ray, sp, level, weight, state, shot};
  for (int k = 0; k < blend.count; ++k) {
    if (blend.weight_of(k) < photon_adc_) continue;
    const Material& m = scene_.materials[blend.material_of(k)];
    photon_texture(here, m.texture, material_point(m, at), colour * blend.weight_of(k));
  }
}

// A patterned texture hands the photon to the textures its pattern picks, each with its share of the energy
// (POV-Ray's ComputeOneTextureColour and ComputeAverageTextureColours with photonPass).
void Tracer::photon_texture(const PhotonHit& at, const RenderTexture& texture, const TexturePoint& tp, Rgb colour) {
  if (!texture.patterned()) return photon_layers(at, texture, tp, colour);
  warps_.push_back(&texture);
  const RenderPigment& pattern = texture.pattern;
  if (pattern.pattern == PatternKind::uv_mapping) {
    photon_texture(at, texture.children.front(), tp.at_uv(), colour);
  } else {
    const TexturePoint p = tp.moved(to_pattern_space(pattern, tp.point));
    if (pattern.pattern == PatternKind::average) {
      double total = 0;
      for (const RenderTexture& c : texture.children) total += c.value;
      for (const RenderTexture& c : texture.children) photon_texture(at, c, p, colour * (c.value / total));
    } else {
      const double value = texture_pattern_value(texture, p);
      const MapChoice m = choose_entries(texture.children, value);
      if (m.prev == m.cur) {
        photon_texture(at, texture.children[m.cur], p, colour);
      } else {
        photon_texture(at, texture.children[m.cur], p, colour * m.fraction);
        photon_texture(at, texture.children[m.prev], p, colour * (1.0 - m.fraction));
      }
    }
  }
  warps_.pop_back();
}

void Tracer::photon_layers(const PhotonHit& at, const RenderTexture& texture, const TexturePoint& tp, Rgb colour) {
  const Ray& ray = at.ray;
  const SurfaceHit& hit = at.sp.hit;
  PhotonShot& shot = at.shot;
  const InteriorRef self = interior_of(hit);
  const Interior& interior = *self.interior;
  const Material& material = scene_.materials[hit.leaf->material];

  // The media of the interiors the photon crossed (POV-Ray computes them on the photon's colour, depositing none).
  if (media_ && at.state.interiors.any_media() && at.state.interiors.all_hollow()) {
    const RayState* outer = media_state_;
    media_state_ = &at.state;
    MediaList list;
    for (int i = 0; i < at.state.interiors.size(); ++i)
      if (const MediaSet* m = at.state.interiors[i].media) list.add(*m);
    colour = media_effect(list, MediaSegment{ray.origin, ray.direction, hit.t, false}).apply(colour);
    media_state_ = outer;
  }
  // The interior's fade over the distance travelled inside it (only with fade_power > 0, as on shadow rays), and the
  // legacy `refraction` factor.
  Rgb attenuation{interior.refraction, interior.refraction, interior.refraction};
  if (at.state.interiors.contains(self)) attenuation = attenuation * shadow_fade(interior, hit.t);
  colour = colour * attenuation;
  shot.depth += hit.t;

  // Stored on every surface after the first bounce, unless the photon only crossed a pass_through object to get
  // here or the object does not collect photons.
  if (at.level > 1 && !shot.pass_prev && material.photons.collect) deposit_photon(at, colour);

  // The layers: their filter for the refracted photon, and each layer's reflection (POV-Ray's list of WNRX).
  Rgb filter{1, 1, 1};
  double trans = 1.0;
  const std::size_t first_reflection = reflections_.size();
  Vec3 top_normal = at.sp.raw_normal, last_normal = at.sp.raw_normal;
  for (const RenderLayer& layer : texture.layers) {
    if (!(trans > photon_adc_)) break;
    const Vec3 normal = layer.normal && quality_.normals ? layer_normal(*layer.normal, at.sp, tp) : at.sp.raw_normal;
    if (&layer == &texture.layers.front()) top_normal = normal;
    last_normal = normal;
    const auto [s, found] = sample_pigment(layer.pigment, tp);
    if (layer.reflects) {
      const double c = -dot(ray.direction, normal);
      const double ior = layer.finish.reflection_fresnel ? relative_ior(self, at.state) : 1.0;
      auto [amount, w] = reflectivity(layer.finish, c, ior, at.weight * trans, true);
      if (const double m = layer.finish.reflection_metallic; m != 0) {
        const double fade = metallic_fade(std::fabs(std::acos(std::clamp(c, -1.0, 1.0))) / (M_PI / 2));
        const Rgb tint = Rgb{1, 1, 1} + (Rgb{s.r, s.g, s.b} - Rgb{1, 1, 1}) * (m * (1.0 - fade));
        amount = Rgb{static_cast<float>(amount.x * tint.x), static_cast<float>(amount.y * tint.y),
                     static_cast<float>(amount.z * tint.z)};
      }
      reflections_.push_back(PendingReflection{amount, w, layer.reflection_exponent_inverse, normal});
    }
    if (found) {
      filter = filter * pass_through(s);
      if (layer.reflects && layer.finish.conserve_energy) {
        const Rgb a = reflections_.back().amount;
        filter = filter * Rgb{std::min(1.0, 1.0 - a.x), std::min(1.0, 1.0 - a.y), std::min(1.0, 1.0 - a.z)};
      }
    }
    trans = std::min(1.0, std::fabs(grey(filter)));
  }

  if (shot.pass_this) {
    // A pass_through object met on the way to the target: the photon goes on in its direction, filtered by the
    // layers (POV-Ray 3.7 builds with PT_FILTER_BEFORE_TARGET), and is neither reflected nor refracted. POV-Ray
    // returns here without taking back the depth.
    reflections_.resize(first_reflection);
    RayState next = at.state;
    if (!next.interiors.remove(self)) next.interiors.append(self);
    photon_trace(Ray{at.sp.point, ray.direction}, colour * filter, at.level,
                 at.weight * std::max(0.0, max_channel(filter)), next, shot);
    return;
  }

  const Light& light = shot.light->light;
  bool total_internal_reflection = false;
  if (allowed(material.photons.refraction, light.photon_refraction) && trans > photon_adc_ && quality_.refraction)
    total_internal_reflection =
        photon_refract(at, top_normal, filter, colour, at.weight * std::max(0.0, max_channel(filter)));

  // Each layer's reflection, with the layer's reflectivity; after total internal reflection those sharing the top
  // layer's normal are skipped. POV-Ray reflects them all about the last layer's normal.
  if (allowed(material.photons.reflection, light.photon_reflection) && quality_.reflection) {
    for (std::size_t i = first_reflection; i < reflections_.size(); ++i) {
      const PendingReflection r = reflections_[i];
      const Vec3 d = top_normal - r.normal;
      const bool same_normal = std::fabs(d.x) <= tolerance::epsilon && std::fabs(d.y) <= tolerance::epsilon &&
                               std::fabs(d.z) <= tolerance::epsilon;
      if (total_internal_reflection && same_normal) continue;
      if (is_black(r.amount)) continue;
      const Rgb reflected =
          r.exponent != 1.0
              ? r.amount * Rgb{std::pow(colour.x, r.exponent), std::pow(colour.y, r.exponent), std::pow(colour.z, r.exponent)}
              : r.amount * colour;
      photon_reflect(at, last_normal, reflected, r.weight * max_channel(r.amount));
    }
  }
  reflections_.resize(first_reflection);
  shot.depth -= hit.t;
}

// The refracted photon, filtered by the layers; an ior-1 surface lets it through unbent. Total internal reflection
// reflects it unfiltered (POV-Ray's ComputeRefractionForPhotons, TraceRefractionRayForPhotons).
bool Tracer::photon_refract(const PhotonHit& at, Vec3 normal, Rgb filter, Rgb colour, double weight) {
  const Ray& ray = at.ray;
  const InteriorRef self = interior_of(at.sp.hit);
  RayState next = at.state;
  const double eta = cross_interior(next.interiors, self);
  if (std::fabs(eta - 1.0) < tolerance::epsilon) {
    photon_trace(Ray{at.sp.point, ray.direction}, colour * filter, at.level, weight, next, at.shot);
    return false;
  }
  const std::optional<Vec3> refracted = refracted_direction(ray.direction, normal, eta);
  if (!refracted) {
    photon_reflect(at, normal, colour, weight);
    return true;
  }
  photon_trace(Ray{at.sp.point, *refracted}, colour * filter, at.level, weight, next, at.shot);
  return false;
}

// The mirrored photon, corrected as reflected rays are when a bent normal would send it into the surface.
void Tracer::photon_reflect(const PhotonHit& at, Vec3 normal, Rgb colour, double weight) {
  photon_trace(Ray{at.sp.point, mirror_direction(at.ray.direction, normal, at.sp.raw_normal)}, colour, at.level, weight,
               at.state, at.shot);
}

// POV-Ray's addSurfacePhoton: the photon's energy is its light's colour over the solid angle (parallel lights: the
// area) it stands for — spread² at unit distance, times the distance travelled squared — with the light's fade
// taken at that distance; the direction stored points back along the last leg.
void Tracer::deposit_photon(const PhotonHit& at, Rgb colour) {
  const PhotonShot& shot = at.shot;
  const RenderLight& l = *shot.light;
  double energy = shot.spread * shot.spread;
  if (l.fades) energy *= 2.0 / (1.0 + std::pow(shot.depth / l.light.fade_distance, l.light.fade_power));
  if (!l.light.parallel) energy *= shot.depth * shot.depth;
  shot.out->push_back(photons::make_photon(at.sp.point, colour * energy, at.ray.origin - at.sp.point));
}

}  // namespace povtrace::render
