// The recursive shading function: a POV-style Whitted trace(ray, level, weight) (STYLE.md (a) step 5) with
// POV-Ray 3.7's finish model (povray-pixel-pipeline.md §2), lights and shadows (§3), transmission and the
// recursion limits (§4), and the background (§5). One Tracer per thread; it allocates nothing per ray.
#pragma once

#include <cstdint>

#include "renderer/render_scene.hpp"

namespace povtrace::render {

enum class ShadingModel { povray, textbook };

struct RayCounts {
  std::uint64_t camera = 0;
  std::uint64_t shadow = 0;
  std::uint64_t secondary = 0;
  RayCounts& operator+=(const RayCounts& o) {
    camera += o.camera; shadow += o.shadow; secondary += o.secondary;
    return *this;
  }
};

// Colour seen along a ray, in working-gamma space, plus its transmit (for alpha output).
struct Radiance {
  Rgb colour;
  double transmit = 0;
};

class Tracer {
 public:
  Tracer(const RenderScene& scene, ShadingModel model) : scene_(scene), model_(model) {}

  // A camera ray (level 1, weight 1).
  Radiance trace_camera_ray(const Ray& ray);
  const RayCounts& counts() const { return counts_; }

 private:
  Radiance trace(const Ray& ray, int level, double weight);
  Radiance shade_hit(const Ray& ray, const SurfaceHit& hit, int level, double weight);
  Radiance shade_material(const Ray& ray, const SurfaceHit& hit, const Material& material, int level, double weight);
  Rgb lit_layer_povray(const RenderLayer& layer, const Colour& pigment, Vec3 point, Vec3 normal, Vec3 view);
  Rgb lit_layer_textbook(const RenderLayer& layer, const Colour& pigment, Vec3 point, Vec3 normal, Vec3 view);
  // Light colour reaching `point` from light `l` before shadowing (spot and fade attenuation), plus L and
  // the distance used by the shadow test. Returns false when the light is cut off (below 1e-10).
  bool light_at(const RenderLight& l, Vec3 point, Rgb& colour, Vec3& to_light, double& distance) const;
  // Shadow factor along the segment point → light: 0 when an opaque object blocks, a filter colour when
  // transparent objects lie in between (pipeline §3).
  Rgb shadow_filter(Vec3 point, Vec3 to_light, double distance);
  Radiance background() const;

  const RenderScene& scene_;
  ShadingModel model_;
  RayCounts counts_;
};

// Pigment colour at a world point (pattern evaluated in the pigment's own space).
Colour evaluate_pigment(const RenderPigment& pigment, Vec3 world_point);

// POV-Ray's empirical metallic highlight fade F(x), x = angle/(π/2) (pipeline §2).
double metallic_fade(double x);

}  // namespace povtrace::render
