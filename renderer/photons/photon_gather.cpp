// Light from the photon map at a shaded point (POV-Ray 3.7's Trace::ComputePhotonDiffuseLight, render/trace.cpp;
// docs/issue20-photons.md §3), written anew: the photons gathered around the point act as lights from the directions
// they arrived from, each shaded by the layer's finish, and the sum is divided by the gathered disc's area.
#include <cmath>

#include "renderer/shading_helpers.hpp"
#include "renderer/tracer.hpp"

namespace povtrace::render {

Rgb Tracer::photon_light(const RenderLayer& layer, const Colour& s, const ShadingPoint& sp, Vec3 normal, Vec3 view,
                         const RayState& state, PhotonGather& g) {
  const Finish& fin = layer.finish;
  if (fin.diffuse == 0 && fin.diffuse_back == 0 && fin.specular == 0 && fin.phong == 0) return {};
  if (!g.done) {
    // The first layer that asks gathers, with its normal flattening the search; the layers below reuse the set.
    g.slot = photon_gather_depth_++;
    if (photon_gathers_.size() <= g.slot) photon_gathers_.resize(g.slot + 1);
    photon_map_->gather_adaptive(sp.point, normal, photon_gathers_[g.slot], photon_scratch_);
    g.done = true;
  }
  const photons::Gathered& found = photon_gathers_[g.slot];
  if (found.found.empty() || !(found.radius > 0)) return {};
  const Rgb pigment{s.r, s.g, s.b};
  const double att = scene_.language_version >= 370 ? 1.0 - s.f - s.t
                                                     : 1.0 - (s.f * std::max({s.r, s.g, s.b}) + s.t);
  // No highlights on a radiosity sample ray's tree (trace.cpp: "NK rad").
  const bool highlights = layer.has_highlights && state.radiosity_depth == 0;
  Rgb sum;
  std::size_t index = 0;
  for (const auto& [distance, photon] : found.found) {
    ++index;
    const Vec3 to_light = photons::photon_direction(*photon);
    // Lambert compensation against the raw normal, limited to 10× so that grazing photons make no bright dots.
    const double cos_raw = std::clamp(dot(sp.raw_normal, to_light), 0.1, 1.0);
    const Rgb colour = photons::photon_colour(*photon) * (1.0 / cos_raw);
    const double c = dot(normal, to_light);
    const bool two_sided = sp.hit.leaf->double_illuminate;
    if (c < tolerance::epsilon && fin.diffuse_back == 0 && !two_sided) continue;   // from behind: only diffuse_back
    const double speckle = fin.crand > 0 ? fin.crand * speckle_random(sp.point, scene_.lights.size() + index) : 0.0;
    sum += one_light(layer, pigment, att, sp.point, normal, view, colour, to_light, c, speckle, highlights, two_sided);
  }
  return sum * (1.0 / (M_PI * found.radius * found.radius));
}

bool Tracer::photons_replace_shadow(const RenderLight& l, const SurfaceHit& crossing) const {
  if (!photon_map_ || lit_ignores_photons_) return false;
  const ObjectPhotons& f = scene_.materials[crossing.leaf->material].photons;
  const std::optional<bool>& light = l.light.photon_refraction;
  return f.target > 0 && f.refraction != false && light != false && (f.refraction == true || light == true);
}

}  // namespace povtrace::render
