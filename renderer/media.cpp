// Media along the rays the tracer follows (POV-Ray 3.7, facts from source/backend/render/trace.cpp and
// docs/issue20-media-study.md):
// - A ray that hits something, is inside interiors and outside every non-hollow object (a hollow ray) gets the
//   media of all those interiors together over its length, applied to the colour of the hit (ComputeTextureColour).
//   A ray that hits nothing gets none of them.
// - Then every hollow ray gets the atmosphere's media over the same length, a miss over BOUND_HUGE, and then fog
//   (TraceRay).
// - A media sample is lit by every light with media_interaction through the ordinary shadow test from the sample
//   point, whose shadow ray starts in the viewing ray's interiors (TestShadow on a copy of the ray).
// - Shadow rays: at each surface they cross, the media of the interiors behind them dim the light (always); the
//   atmosphere and fog dim each stretch only for lights with media_interaction and media_attenuation.
#include "renderer/tracer.hpp"

namespace povtrace::render {

MediaEffect Tracer::media_effect(const MediaList& media, const MediaSegment& segment) {
  MediaRandom random(media_seed(segment.origin, segment.direction, segment.depth));
  return integrate_media(media, segment, scene_.lights, *this, random);
}

Radiance Tracer::with_media(const Ray& ray, double depth, bool hit, const RayState& state, Radiance r) {
  struct StateScope {   // media samples' shadow rays start in this ray's interiors
    const RayState*& current;
    const RayState* outer;
    ~StateScope() { current = outer; }
  } scope{media_state_, media_state_};
  media_state_ = &state;
  const MediaSegment segment{ray.origin, ray.direction, depth, false};
  const auto apply = [&](const MediaList& list) {
    const MediaEffect e = media_effect(list, segment);
    r.colour = e.apply(r.colour);
    r.transmit *= grey(e.transmittance);
  };
  if (hit && state.interiors.any_media()) {
    MediaList list;
    for (int i = 0; i < state.interiors.size(); ++i)
      if (const MediaSet* m = state.interiors[i].media) list.add(*m);
    apply(list);
  }
  if (scene_.atmosphere) {
    MediaList list;
    list.add(*scene_.atmosphere);
    apply(list);
  }
  return r;
}

std::optional<MediaLighting::Arrival> Tracer::arrival(std::size_t index, Vec3 point) {
  const RenderLight& l = scene_.lights[index];
  const std::optional<LightRay> lr = light_at(l, point);
  if (!lr) return std::nullopt;
  const Rgb colour = shadowed_light(l, point, lr->to_light, lr->distance, lr->colour, *media_state_);
  if (near_zero(colour)) return std::nullopt;
  return Arrival{colour, lr->to_light};
}

Rgb Tracer::shadow_interior_media(const Ray& ray, double from, double to, const InteriorList& in) {
  MediaList list;
  for (int i = 0; i < in.size(); ++i)
    if (const MediaSet* m = in[i].media) list.add(*m);
  const MediaSegment segment{ray.origin + ray.direction * from, ray.direction, to - from, true};
  return media_effect(list, segment).transmittance;
}

Rgb Tracer::shadow_atmosphere(const RenderLight& l, const Ray& ray, double from, double to, Rgb f, bool hollow,
                              bool at_surface) {
  if (!shadow_atmosphere_ || !(l.light.media_interaction && l.light.media_attenuation)) return f;
  if (all_below(f, tolerance::epsilon)) return f;
  const Ray stretch{ray.origin + ray.direction * from, ray.direction};
  if (scene_.atmosphere && (hollow || at_surface)) {
    MediaList list;
    list.add(*scene_.atmosphere);
    f = f * media_effect(list, MediaSegment{stretch.origin, stretch.direction, to - from, true}).transmittance;
  }
  if (fog_ && hollow) f = f * fog_on_shadow(stretch, to - from);
  return f;
}

}  // namespace povtrace::render
