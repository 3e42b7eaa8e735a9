// Whitted tracing with POV-Ray 3.7's shading (povray-pixel-pipeline.md §2–§5). Comments cite the section of
// that document whose behaviour each step reproduces.
#include "renderer/tracer.hpp"

#include <algorithm>
#include <cmath>

namespace povtrace::render {

namespace {
Rgb mul(Rgb a, Rgb b) { return {a.x * b.x, a.y * b.y, a.z * b.z}; }
double max_channel(Rgb c) { return std::max({c.x, c.y, c.z}); }
bool all_below(Rgb c, double e) { return c.x < e && c.y < e && c.z < e; }

// Smooth step used by spotlights' falloff zone (§3): 0 below a, 1 at or above b, 3s²−2s³ between.
double smoothstep(double a, double b, double x) {
  if (x >= b) return 1.0;
  if (x <= a) return 0.0;
  const double s = (x - a) / (b - a);
  return s * s * (3.0 - 2.0 * s);
}

// Light arriving through a pigment: filter tints by the colour, transmit does not (§3, §4).
Rgb pass_through(const Colour& s) { return Rgb{s.r, s.g, s.b} * s.f + Rgb{s.t, s.t, s.t}; }

constexpr double kPhongCutoff = 0.0008;       // phong highlights with size ≥ 60 vanish below this (§2)
constexpr double kPhongCutoffSize = 60.0;
}  // namespace

double metallic_fade(double x) {
  const double d = x - 1.12;
  return std::clamp(0.014567225 / (d * d) - 0.011612903, 0.0, 1.0);
}

Radiance Tracer::trace_camera_ray(const Ray& ray) {
  ++counts_.camera;
  return trace(ray, 1, 1.0);
}

// Levels beyond max_trace_level and rays lighter than adc_bailout yield black, not the background (§4).
Radiance Tracer::trace(const Ray& ray, int level, double weight) {
  if (level > scene_.settings.max_trace_level || weight < scene_.settings.adc_bailout) return {};
  const Hit hit = scene_.accelerator.closest_hit(ray, tolerance::min_isect_depth, tolerance::bound_huge);
  if (!hit.found()) return background();
  return shade_hit(ray, hit.surface, level, weight);
}

Radiance Tracer::background() const { return {scene_.background, scene_.background_transmit}; }

Radiance Tracer::shade_hit(const Ray& ray, const SurfaceHit& hit, int level, double weight) {
  const MaterialBlend blend = materials_at(hit);
  if (blend.count == 1) return shade_material(ray, hit, scene_.materials[blend.material[0]], level, weight);
  // A mesh triangle with a texture_list: each texture shaded whole, the results blended by their weights; weights
  // below adc_bailout are skipped (POV-Ray's ComputeTextureColour).
  Radiance out;
  for (int k = 0; k < blend.count; ++k) {
    if (blend.weight[k] < scene_.settings.adc_bailout) continue;
    const Radiance r = shade_material(ray, hit, scene_.materials[blend.material[k]], level, weight);
    out.colour += r.colour * blend.weight[k];
    out.transmit += r.transmit * blend.weight[k];
  }
  return out;
}

Radiance Tracer::shade_material(const Ray& ray, const SurfaceHit& hit, const Material& material, int level,
                                double weight) {
  const Primitive& prim = *hit.leaf;
  const Vec3 point = ray.origin + ray.direction * hit.t;
  const Vec3 raw_normal = surface_normal(hit, point);
  // Every surface is two-sided: shade on the side the ray sees (§2 "Normal").
  const Vec3 normal = dot(raw_normal, ray.direction) > 0 ? -raw_normal : raw_normal;

  // Layers top first; each is weighted by what the layers above let through (§2 "Layers").
  Radiance out;
  Rgb filter{1, 1, 1};
  double trans = 1.0;
  for (const RenderLayer& layer : material.layers) {
    const Colour s = evaluate_pigment(layer.pigment, point);
    const Rgb lit = model_ == ShadingModel::povray ? lit_layer_povray(layer, s, point, normal, ray.direction)
                                                   : lit_layer_textbook(layer, s, point, normal, ray.direction);
    out.colour += mul(lit, filter);
    filter = mul(filter, pass_through(s));
    trans = std::min(1.0, std::fabs(grey(filter)));
    if (trans <= scene_.settings.adc_bailout) break;
  }
  if (trans <= scene_.settings.adc_bailout) return out;

  // Transmission (§4 "Transmission/refraction"): relative ior from the side the ray comes from.
  const Vec3 outward = prim.inverse ? -raw_normal : raw_normal;
  const bool entering = dot(outward, ray.direction) < 0;
  const double ior = material.interior.ior;
  const double eta = entering ? 1.0 / ior : ior;
  const double next_weight = weight * max_channel(filter);
  ++counts_.secondary;
  if (std::fabs(eta - 1.0) < tolerance::epsilon) {
    // An ior-1 surface continues the ray without using up a trace level.
    const Radiance behind = trace(Ray{point, ray.direction}, level, next_weight);
    out.colour += mul(filter, behind.colour);
    out.transmit = behind.transmit * trans;
    return out;
  }
  const double m = std::fabs(dot(ray.direction, normal));
  const double k = 1.0 + eta * eta * (m * m - 1.0);
  if (k < 0) {
    // Total internal reflection: the mirror ray, not filtered by the layers (§4 TIR).
    const Vec3 mirrored = ray.direction - normal * (2.0 * dot(ray.direction, normal));
    const Radiance reflected = trace(Ray{point, mirrored}, level + 1, next_weight);
    out.colour += reflected.colour;
    return out;
  }
  const Vec3 refracted = ray.direction * eta + normal * (eta * m - std::sqrt(k));
  const Radiance behind = trace(Ray{point, normalize(refracted)}, level + 1, next_weight);
  out.colour += mul(filter, behind.colour);
  out.transmit = behind.transmit * trans;
  return out;
}

bool Tracer::light_at(const RenderLight& l, Vec3 point, Rgb& colour, Vec3& to_light, double& distance) const {
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
  colour = l.colour;
  if (l.light.spotlight) {
    const double cos_angle = -dot(to_light, l.spot_axis);
    if (cos_angle <= 0) return false;
    double a = l.light.tightness != 0 ? std::pow(cos_angle, l.light.tightness) : 1.0;
    if (cos_angle < l.cos_radius) a *= smoothstep(l.cos_falloff, l.cos_radius, cos_angle);
    colour *= a;
  }
  if (l.fades) colour *= 2.0 / (1.0 + std::pow(distance / l.light.fade_distance, l.light.fade_power));
  return !all_below(colour, tolerance::epsilon);
}

Rgb Tracer::shadow_filter(Vec3 point, Vec3 to_light, double distance) {
  if (!scene_.any_casts_shadow) return {1, 1, 1};
  ++counts_.shadow;
  Rgb f{1, 1, 1};
  // Hits count only with 1e-3 < t < distance − 1e-3 (§3, §8 SHADOW_TOLERANCE).
  const Ray ray{point, to_light};
  scene_.accelerator.for_each_shadow_hit(
      ray, tolerance::shadow, distance - tolerance::shadow, [&](std::uint32_t, const SurfaceHit& hit) {
        const MaterialBlend blend = materials_at(hit);
        if (blend.count == 1 && scene_.materials[blend.material[0]].opaque) {
          f = {0, 0, 0};
          return false;
        }
        // A transparent object filters at every surface crossing, through all its layers (§3); a texture_list
        // triangle by the weighted sum of its textures' filters.
        const Vec3 at = point + to_light * hit.t;
        Rgb through{0, 0, 0};
        for (int k = 0; k < blend.count; ++k) {
          const Material& m = scene_.materials[blend.material[k]];
          Rgb layers = m.opaque ? Rgb{0, 0, 0} : Rgb{1, 1, 1};
          if (!m.opaque)
            for (const RenderLayer& layer : m.layers)
              layers = mul(layers, pass_through(evaluate_pigment(layer.pigment, at)));
          through += layers * blend.weight[k];
        }
        f = mul(f, through);
        return !all_below(f, tolerance::epsilon);
      });
  return f;
}

// POV-Ray's finish model for one layer (§2): ambient and emission scaled by opacity; per light, diffuse with
// brilliance, Phong and Blinn highlights (not scaled by opacity), metallic tint, back-side diffuse.
Rgb Tracer::lit_layer_povray(const RenderLayer& layer, const Colour& s, Vec3 point, Vec3 normal, Vec3 view) {
  const Finish& fin = layer.finish;
  const Rgb pigment{s.r, s.g, s.b};
  const double att = scene_.language_version >= 370 ? 1.0 - s.f - s.t
                                                     : 1.0 - (s.f * std::max({s.r, s.g, s.b}) + s.t);
  Rgb out = mul(pigment * att, mul(rgb_of(fin.ambient), rgb_of(scene_.settings.ambient_light)) + rgb_of(fin.emission));
  if (fin.diffuse == 0 && fin.diffuse_back == 0 && !layer.has_highlights) return out;

  for (const RenderLight& l : scene_.lights) {
    Rgb lc;
    Vec3 to_light;
    double distance;
    if (!light_at(l, point, lc, to_light, distance)) continue;
    const double c = dot(normal, to_light);
    const bool behind = c < tolerance::epsilon;
    if (behind && fin.diffuse_back == 0) continue;   // a light behind the surface gives nothing at all
    if (!l.light.shadowless) {
      lc = mul(lc, shadow_filter(point, to_light, distance));
      if (all_below(lc, tolerance::epsilon)) continue;
    }
    if (behind) {
      out += mul(pigment, lc) * (fin.diffuse_back * att * std::pow(std::fabs(c), fin.brilliance));
      continue;
    }
    if (fin.diffuse != 0)
      out += mul(pigment, lc) * (fin.diffuse * att * (fin.brilliance == 1.0 ? c : std::pow(c, fin.brilliance)));
    if (l.light.shadowless || !layer.has_highlights) continue;   // fill lights give no highlights

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
  }
  return out;
}

// The seed chapter's direct illumination (../shared/seed/): ka·La·S + Σ kd(N·L)Ld·S + ks(R·E)^n and
// ks(N·H)^n tinted by (1−p)S + p, negative terms dropped. POV-Ray's finish maps onto ka, kd, ks, n, p as the
// README states; shadows use the same test as POV-Ray mode.
Rgb Tracer::lit_layer_textbook(const RenderLayer& layer, const Colour& s, Vec3 point, Vec3 normal, Vec3 view) {
  const Finish& fin = layer.finish;
  const Rgb pigment{s.r, s.g, s.b};
  Rgb out = mul(mul(rgb_of(scene_.settings.ambient_light), rgb_of(fin.ambient)), pigment);
  const double p = 1.0 - fin.metallic;
  const Rgb plastic = pigment * (1.0 - p) + Rgb{p, p, p};
  const Vec3 eye = -view;
  for (const RenderLight& l : scene_.lights) {
    Rgb lc;
    Vec3 to_light;
    double distance;
    if (!light_at(l, point, lc, to_light, distance)) continue;
    if (!l.light.shadowless) {
      lc = mul(lc, shadow_filter(point, to_light, distance));
      if (all_below(lc, tolerance::epsilon)) continue;
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
