// The recursive shading function: a POV-style Whitted trace(ray, level, weight) (STYLE.md (a) step 5) with
// POV-Ray 3.7's finish model (povray-pixel-pipeline.md §2), lights and shadows (§3), transmission and the
// recursion limits (§4), and the background (§5). One Tracer per thread; it allocates nothing per ray.
#pragma once

#include <cmath>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "renderer/interior_list.hpp"
#include "renderer/media/media_integrator.hpp"
#include "renderer/photons/photon_map.hpp"
#include "renderer/radiosity/gather.hpp"
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

// What a render quality level computes, as POV-Ray 3.7 maps +Q0…+Q9 to its quality flags (povrayold.h QUALITY_n,
// backend/scene/view.cpp) and tests them in its tracer (backend/render/trace.cpp, texture/pigment.cpp):
//   0–1  full_ambient: a surface shows its pigment's colour, unlit (no finish, no transparency, no reflection)
//   0–5  quick colours: a pigment with a quick_color shows that colour (applied when the scene is built:
//        BuildOptions::quick_colours)
//   4–   shadows
//   5–   area lights sampled over their area (below: shadows from their centre as from a point light)
//   6–   transmitted (refracted) rays
//   8–   reflected rays and normal perturbation
//   9    fog (POV-Ray's Q_VOLUME: also media and rainbows), and Q_ADVANCED_LIGHT: radiosity and photons (applied
//        when the scene is built: BuildOptions::quality); Q_SUBSURFACE (subsurface scattering) is not rendered
// 10 and 11 are 9 (the option parser clips them, as povray does).
struct Quality {
  bool full_ambient = false;
  bool shadows = true;
  bool area_lights = true;
  bool refraction = true;
  bool reflection = true;
  bool normals = true;
  bool fog = true;
  static Quality at_level(int level);
  static bool quick_colours_at(int level) { return level <= 5; }
};

// With radiosity (RenderScene::radiosity), the Tracer is also the SampleTracer its Gatherer shoots sample rays
// through (renderer/radiosity/gather.hpp).
class Tracer : private radiosity::SampleTracer, private MediaLighting {
 public:
  Tracer(const RenderScene& scene, ShadingModel model, Quality quality = {});

  // A camera ray (level 1, weight 1), starting inside the interiors that contain the camera. A radiosity pretrace
  // ray (`pretrace`) is traced only for the radiosity queries of its tree: as POV-Ray does for pretrace rays
  // (trace.cpp, IsPretraceRay), its tree's surfaces skip the lights (sample rays traced from it do not).
  Radiance trace_camera_ray(const Ray& ray, bool pretrace = false);
  const RayCounts& counts() const { return counts_; }
  // Empties POV-Ray's shadow cache (see shadow_cache_): done at the start of every block, so that an image does
  // not depend on which thread rendered which block before.
  void forget_shadow_cache() { shadow_cache_.clear(); }
  // Starts a block: forgets the shadow cache and, with radiosity, starts the block's private samples and direction
  // cursors (POV-Ray's BeforeTile) under tile id `tile` in radiosity pass `pass` (pretrace 1, 2, … or the final
  // render).
  void begin_block(int tile, int pass = radiosity::final_pass_id);
  // The radiosity evaluator of this tracer (null without radiosity): its block samples, its global level.
  radiosity::Gatherer* gatherer() { return gatherer_.get(); }

  // The photon pass (photons/photon_trace.cpp, POV-Ray's PhotonTrace): one photon from a light toward a target,
  // followed through the reflections and refractions the objects' and the light's photon flags allow; photons are
  // left on the surfaces it reaches after its first bounce. What POV-Ray keeps per thread for the photon in flight
  // is kept here.
  struct PhotonShot {
    const RenderLight* light = nullptr;
    std::uint32_t target = 0;          // the target shot at (index into RenderScene::photon_targets)
    double spread = 0;                 // the angular (parallel lights: spatial) spacing of the photons
    bool hit_target = false;           // the target was reached first (the autostop test reads it)
    double depth = 0;                  // distance travelled from the light
    bool pass_prev = true, pass_this = false;   // POV-Ray's passThruPrev / passThruThis
    std::vector<photons::Photon>* out = nullptr;
  };
  // `depth`: how far the photon has come from the light already (through a projected_through object).
  void shoot_photon(const Ray& ray, Rgb colour, const std::vector<InteriorRef>& interiors, PhotonShot& shot,
                    double depth = 0);

 private:
  // What a ray carries besides its geometry: the interiors it is in, and whether a miss may show the background's
  // transparency (POV-Ray clears that for reflected rays and everything traced from them, pipeline §5).
  // With radiosity, also the radiosity depth of the surfaces it hits (POV-Ray's ticket.radiosityRecursionDepth,
  // which only sample rays and the rays traced from them raise; > 0 is POV-Ray's IsRadiosityRay, study §1.1).
  struct RayState {
    InteriorList interiors;
    bool alpha_background = true;
    int radiosity_depth = 0;
    bool pretrace = false;   // a radiosity pretrace ray or one traced from it, not a sample ray (trace_camera_ray)
  };
  // One layer's reflection, computed in the layer loop and traced after the transmitted ray (pipeline §4).
  struct PendingReflection {
    Rgb amount;            // reflectivity colour
    double weight = 0;     // ray weight for adc_bailout
    double exponent = 1;   // 1 / `exponent`
    Vec3 normal;           // the layer's normal (facing the viewer)
    const Finish* finish = nullptr;   // the layer's finish (irid tints what it reflects)
  };

  Radiance trace(const Ray& ray, int level, double weight, const RayState& state);
  Radiance shade_hit(const Ray& ray, const SurfaceHit& hit, int level, double weight, const RayState& state);
  // What every texture shading the same hit shares.
  struct ShadingPoint {
    const SurfaceHit& hit;
    Vec3 point;        // the world point
    Vec3 raw_normal;   // the surface normal facing the ray
    std::size_t warps_from = 0;   // this hit's patterned textures start here in warps_ (rays traced from a layer
                                  // push their own above them)
  };
  Radiance shade_material(const Ray& ray, const SurfaceHit& hit, const Material& material, const TexturePoint& at,
                          int level, double weight, const RayState& state);
  Radiance shade_texture(const Ray& ray, const ShadingPoint& sp, const RenderTexture& texture, const TexturePoint& at,
                         int level, double weight, const RayState& state);
  Radiance shade_layers(const Ray& ray, const ShadingPoint& sp, const RenderTexture& texture, const TexturePoint& at,
                        int level, double weight, const RayState& state);
  template <bool Radiosity>   // the layer loop, with the radiosity term or without
  Radiance shade_layers_as(const Ray& ray, const ShadingPoint& sp, const RenderTexture& texture, const TexturePoint& at,
                           int level, double weight, const RayState& state);
  // +Q0/+Q1: the pigment colour alone (POV-Ray's Q_FULL_AMBIENT).
  Radiance unlit_layers(const RenderTexture& texture, const TexturePoint& at) const;
  Vec3 layer_normal(const RenderNormal& normal, const ShadingPoint& sp, const TexturePoint& at) const;
  // Fake caustics of the surface a shadow ray crosses (interior `caustics`, POV-Ray's ComputeShadowTexture).
  struct CausticsAt {
    Vec3 raw_normal;    // the surface normal, facing against the shadow ray
    Vec3 direction;     // the shadow ray's
    double exponent;    // the interior's caustics (45 × the written value)
    std::vector<const RenderTexture*>* path;   // patterned textures passed on the way down (their normal warps)
  };
  Rgb texture_filter(const RenderTexture& texture, const TexturePoint& at, const CausticsAt* caustics = nullptr) const;
  // 1 + |N·L|^caustics for one layer, N its normal (perturbed as when it is shaded).
  double caustics_factor(const RenderLayer& layer, const CausticsAt& c, const TexturePoint& at) const;
  // What light keeps crossing the surface at `hit` toward a light: the product over the material's layers of
  // (S·f + t), or for a texture_list triangle the weighted sum over its textures; black when it stops it.
  Rgb filter_through(const SurfaceHit& hit, Vec3 at, Vec3 direction);
  MaterialBlend materials_facing(const SurfaceHit& hit, Vec3 point, Vec3 direction) const;
  // A hit being shaded and the ray that found it: where its transmitted and reflected rays start.
  struct HitContext {
    const Ray& ray;
    const ShadingPoint& sp;
    int level;
    double weight;          // the weight of `ray`
    const RayState& state;
  };
  // What the transmitted ray adds to the hit's colour, and the alpha it sets (none after total reflection).
  struct Transmission {
    Rgb colour;
    double transmit = 0;
    bool total_internal_reflection = false;
  };
  // The transmitted ray (refracted, continued through ior 1, or totally reflected) of a hit, with interior fade,
  // seen through the layers' `filter` (`trans` its grey); `normal` is the top layer's.
  Transmission transmit(const HitContext& at, Vec3 normal, Rgb filter, double trans, const Finish& top_finish);
  // `irid`: the reflecting layer's finish, when its irid tints the reflected colour.
  Radiance trace_reflection(const HitContext& at, Vec3 normal, double reflected_weight, const Finish* irid = nullptr);
  // Relative ior n_to/n_from for fresnel reflection at a surface of `self` (POV-Ray's ComputeRelativeIOR).
  double relative_ior(const InteriorRef& self, const RayState& state) const;
  InteriorRef interior_of(const SurfaceHit& hit) const;
  // The radiosity values of one shade_layers call (POV-Ray computes each side at most once per textured hit).
  // Only the flags are initialised: shade_layers makes one per call, with or without radiosity.
  struct AmbientSides {
    bool front_done = false, back_done = false;
    double front[3], back[3];   // valid once *_done
  };
  // The radiosity term of one layer (trace.cpp ComputeLightedTexture): S·A·att·diffuse_raw, plus the back side's
  // with diffuse_back; A is computed for the first layer whose largest possible contribution passes the bailout.
  [[gnu::noinline]] Rgb radiosity_layer(const RenderLayer& layer, const Colour& pigment, Rgb filter, const ShadingPoint& sp,
                      Vec3 normal, double weight, const RayState& state, AmbientSides& sides);
  radiosity::SampleRayResult trace_sample(Vec3 origin, Vec3 direction, const radiosity::SampleRayParams& p) override;
  template <bool Radiosity>   // the scene has radiosity: sample rays get no highlights
  Rgb lit_layer_povray(const RenderLayer& layer, const Colour& pigment, Vec3 point, Vec3 normal, Vec3 view,
                       const RayState& state, const SurfaceHit& hit);
  Rgb lit_layer_textbook(const RenderLayer& layer, const Colour& pigment, Vec3 point, Vec3 normal, Vec3 view,
                         const RayState& state);
  // Light reaching a point from one light before shadowing.
  struct LightRay {
    Rgb colour;      // after spot and fade attenuation
    Vec3 to_light;   // L
    double distance; // how far the shadow test looks
  };
  // The light reaching `point` from light `l`; none when it is cut off (below 1e-10).
  std::optional<LightRay> light_at(const RenderLight& l, Vec3 point) const;
  std::optional<LightRay> cylinder_light_at(const RenderLight& l, Vec3 point) const;
  // Shadow factor along the segment point → light `l`: 0 when an opaque object blocks, a filter colour when
  // transparent objects lie in between (pipeline §3).
  Rgb shadow_filter(const RenderLight& l, Vec3 point, Vec3 to_light, double distance, const RayState& state);
  // POV-Ray's walk along the shadow ray, with its shadow cache.
  // Crossings count up to `reach` (the light's distance, or less with projected_through).
  Rgb povray_shadow_walk(const RenderLight& l, const Ray& ray, double distance, double reach, const RayState& state);
  template <class Crossings>
  void add_next_crossing_of(std::uint32_t primitive, const Ray& ray, double at, double last, Crossings& crossings,
                            std::size_t k) const;
  std::uint32_t& shadow_cache_slot(const RenderLight& l);
  bool cached_occluder_blocks(std::uint32_t primitive, const Ray& ray, double distance) const;
  bool opaque_at(const SurfaceHit& hit) const;   // one material, and it lets no light through
  // The light colour `colour` (at the light's centre) after the shadow test: one ray for a point light, the
  // combined samples of an area light (area_light.cpp).
  Rgb shadowed_light(const RenderLight& l, Vec3 point, Vec3 to_light, double distance, Rgb colour,
                     const RayState& state);
  struct AreaSampling;
  Rgb area_light_shadow(const RenderLight& l, Vec3 point, Vec3 to_light, Rgb colour, const RayState& state);
  Rgb area_sample(const AreaSampling& s, int u, int v);
  Rgb area_subset(const AreaSampling& s, int u1, int v1, int u2, int v2, int level);
  Radiance background(Vec3 direction, const RayState& state) const;
  // Fog over `depth` along the ray, applied to what the ray sees (fog.cpp).
  Radiance with_fog(const Ray& ray, double depth, Radiance r) const;
  Rgb fog_on_shadow(const Ray& ray, double depth) const;   // what fog lets through along a shadow ray
  // The rainbows seen along the ray, `depth` away (rainbow.cpp).
  Radiance with_rainbows(const Ray& ray, double depth, Radiance r) const;
  // Media over `depth` along the ray (media.cpp): the media of the interiors it is in when it hit something, then
  // the atmosphere's, as POV-Ray applies them (ComputeTextureColour, then TraceRay).
  Radiance with_media(const Ray& ray, double depth, bool hit, const RayState& state, Radiance r);
  MediaEffect media_effect(const MediaList& media, const MediaSegment& segment);
  // The light a media sample receives (MediaLighting; POV-Ray's TestShadow from the sample point).
  std::optional<Arrival> arrival(std::size_t index, Vec3 point) override;
  // What the interiors' media between `from` and `to` along a shadow ray let through (media.cpp).
  Rgb shadow_interior_media(const Ray& ray, double from, double to, const InteriorList& in);
  // A shadow ray's stretch from `from` to `to` through the atmosphere's media and fog, for lights with
  // media_attenuation (POV-Ray's ComputeShadowMedia); `hollow`: the shadow ray is outside non-hollow objects;
  // `at_surface`: the stretch ends at a surface (POV-Ray applies the media there even inside non-hollow objects).
  Rgb shadow_atmosphere(const RenderLight& l, const Ray& ray, double from, double to, Rgb f, bool hollow,
                        bool at_surface);
  Radiance legacy_background(Vec3 sky_point, const RayState& state) const;
  // What one light of colour `lc` from `to_light` (c = N·L) adds to a layer (diffuse, diffuse_back, highlights).
  Rgb one_light(const RenderLayer& layer, Rgb pigment, double att, Vec3 point, Vec3 normal, Vec3 view, Rgb lc,
                Vec3 to_light, double c, double speckle, bool highlights, bool double_illuminate = false) const;
  // irid: the thin-film factor on light arriving along `incoming` and leaving toward the eye (ComputeIridColour).
  Rgb irid_factor(const Finish& fin, Vec3 incoming, Vec3 view, Vec3 normal, Vec3 point) const;

  // ---- photon pass (photons/photon_trace.cpp) ----
  struct PhotonHit {
    const Ray& ray;
    const ShadingPoint& sp;
    int level;          // POV-Ray's trace level of this hit (1 for the light's ray)
    double weight;
    const RayState& state;
    PhotonShot& shot;
  };
  void photon_trace(const Ray& ray, Rgb colour, int level, double weight, const RayState& state, PhotonShot& shot);
  void photon_surface(const Ray& ray, const SurfaceHit& hit, Rgb colour, int level, double weight,
                      const RayState& state, PhotonShot& shot);
  void photon_texture(const PhotonHit& at, const RenderTexture& texture, const TexturePoint& tp, Rgb colour);
  void photon_layers(const PhotonHit& at, const RenderTexture& texture, const TexturePoint& tp, Rgb colour);
  bool photon_refract(const PhotonHit& at, Vec3 normal, Rgb filter, Rgb colour, double weight);
  void photon_reflect(const PhotonHit& at, Vec3 normal, Rgb colour, double weight);
  void deposit_photon(const PhotonHit& at, Rgb colour);
  // ---- photon gather (photons/photon_gather.cpp, POV-Ray's ComputePhotonDiffuseLight) ----
  // The photons around a shaded point, gathered once per textured hit by the first layer that asks.
  struct PhotonGather {
    bool done = false;
    std::size_t slot = 0;   // in photon_gathers_
  };
  Rgb photon_light(const RenderLayer& layer, const Colour& pigment, const ShadingPoint& sp, Vec3 normal, Vec3 view,
                   const RayState& state, PhotonGather& g);
  // A photon target the light's photons were shot at stops its shadow ray outright (the light reaches the surface
  // through the photons instead), unless the lit surface ignores photons (POV-Ray's ComputeShadowColour).
  bool photons_replace_shadow(const RenderLight& l, const SurfaceHit& crossing) const;

  const RenderScene& scene_;
  ShadingModel model_;
  Quality quality_;
  bool fog_;   // the scene has fog and the quality level shows it
  bool media_;  // the scene has media and the quality level shows them (POV-Ray's Q_VOLUME, +Q9)
  bool rainbows_;   // the scene has a rainbow and the quality level shows it (Q_VOLUME too)
  // Some light's shadow rays pass through the atmosphere's media or fog (media_interaction and media_attenuation):
  // shadow rays must know whether they are outside non-hollow objects.
  bool shadow_atmosphere_ = false;
  const RayState* media_state_ = nullptr;   // the ray whose media are being sampled (their shadow rays start in its
                                            // interiors)
  // A hit's transmitted ray is traced when the layers let through more than this: adc_bailout, or never below +Q6
  // (one comparison either way: the default path pays nothing for the quality level).
  double transmit_bailout_;
  // POV-Ray's ticket limits: the deepest trace level and the ADC bailout. The scene's, except while a radiosity
  // sample ray is traced (its own, study §4.4).
  int max_level_;
  double adc_bailout_;
  std::unique_ptr<radiosity::Gatherer> gatherer_;   // with radiosity only
  bool sample_volume_ = false;          // sample rays see fog: radiosity's `media on` (POV-Ray's Q_VOLUME, §7)
  std::size_t shadow_cache_base_ = 0;   // 2·lights while a sample ray is traced: POV-Ray's radiosity tracer has
                                        // shadow caches of its own
  RayCounts counts_;
  std::vector<PendingReflection> reflections_;   // a stack shared by the recursion (entries by index)
  std::vector<const RenderTexture*> warps_;       // the patterned textures above the one being shaded
  std::vector<Rgb> area_grid_;                    // area light samples of the point being shaded
  // POV-Ray's shadow cache (trace.cpp TracePointLightShadowRay): per light, the last object that alone blocked a shadow ray, kept apart for the shadow rays of camera-ray hits
  // (slot 2·light) and of deeper hits (2·light + 1); ~0u when empty. POV-Ray tests it first, with only
  // MIN_ISECT_DEPTH as near limit instead of SHADOW_TOLERANCE, which is what shadows tiny scenes more.
  std::vector<std::uint32_t> shadow_cache_;
  int shading_level_ = 1;   // the trace level of the hit being shaded (which cache slot its shadow rays use)
  // Photons: the map (null without), the photon pass's limits, the lit object's `collect off` as its shadow rays
  // need it, and the gathered photons of the textured hits being shaded (a stack: radiosity nests shading).
  const photons::PhotonMap* photon_map_ = nullptr;
  int photon_max_level_ = 5;
  double photon_adc_ = 1.0 / 255.0;
  bool lit_ignores_photons_ = false;
  std::vector<photons::Gathered> photon_gathers_;
  std::size_t photon_gather_depth_ = 0;
  std::vector<double> photon_scratch_;
};

// A pigment's colour at a point, and POV-Ray's Compute_Pigment result: not found where only image maps used
// `once` were met off their image.
struct PigmentSample {
  Colour colour;
  bool found = true;
};
// The pigment at a point (pattern evaluated in the pigment's own space).
PigmentSample sample_pigment(const RenderPigment& pigment, const TexturePoint& at);
inline Colour evaluate_pigment(const RenderPigment& pigment, const TexturePoint& at) {
  return sample_pigment(pigment, at).colour;
}
inline Colour evaluate_pigment(const RenderPigment& pigment, Vec3 point) {
  return evaluate_pigment(pigment, TexturePoint(point));
}
// The point in the pigment's pattern space: its transforms and warps in POV-Ray's order (Warp_EPoint).
Vec3 to_pattern_space(const RenderPigment& pigment, Vec3 world_point);

// POV-Ray's empirical metallic highlight fade F(x), x = angle/(π/2) (pipeline §2).
double metallic_fade(double x);

}  // namespace povtrace::render
