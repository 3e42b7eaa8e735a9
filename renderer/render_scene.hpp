// The render-ready scene: built once from a SceneDescription (build_render_scene), immutable afterwards.
// Everything per-ray code needs is precomputed here: world-space primitives in a BVH, materials with their
// layers top-first, light directions, the camera's vectors, the working-gamma decode of the output.
#pragma once

#include <string>
#include <string_view>

#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "scene/object_geometry.hpp"
#include "scene/description.hpp"
#include "renderer/geometry.hpp"
#include "renderer/interior_list.hpp"
#include "renderer/pattern/pattern.hpp"
#include "renderer/pattern/image_map.hpp"
#include "renderer/pattern/pattern.hpp"
#include "renderer/radiosity/render_settings.hpp"

namespace povtrace::render {

// RGB triple for shading arithmetic (filter/transmit are carried separately where POV-Ray uses them).
using Rgb = Vec3;
inline Rgb rgb_of(const Colour& c) { return {c.r, c.g, c.b}; }
// POV-Ray's intensity weights (pipeline notation grey()).
inline double grey(const Rgb& c) { return 0.297 * c.x + 0.589 * c.y + 0.114 * c.z; }
inline bool all_below(Rgb c, double e) { return c.x < e && c.y < e && c.z < e; }
// A light colour POV-Ray treats as no light: every channel within EPSILON of 0. By magnitude, so that a negative
// light (color -0.9, which takes light away) still counts, as in POV-Ray's ComputeOneDiffuseLight.
inline bool near_zero(Rgb c) {
  return std::fabs(c.x) < tolerance::epsilon && std::fabs(c.y) < tolerance::epsilon && std::fabs(c.z) < tolerance::epsilon;
}

// Where a texture is evaluated: the point (the world point, or the hit's <u, v, 0> on a uv-mapped object, or the
// point a patterned texture passes down to its textures) and the hit's uv coordinates, which `uv_mapping`
// pigments, normals and textures read.
struct TexturePoint {
  TexturePoint() = default;
  explicit TexturePoint(Vec3 p, double u_ = 0, double v_ = 0) : point(p), u(u_), v(v_) {}
  Vec3 point;
  double u = 0, v = 0;
  // The surface being shaded, for slope and aoi; null away from a surface (they are then 0, as in POV-Ray).
  const ShadingSurface* surface = nullptr;
  // The same surface and uv at another point (a pattern's space), or at <u, v, 0> (uv_mapping).
  TexturePoint moved(Vec3 p) const {
    TexturePoint r = *this;
    r.point = p;
    return r;
  }
  TexturePoint at_uv() const { return moved({u, v, 0.0}); }
};

// One step from the pigment's outer space toward pattern space: an inverse transform, then (if any) a turbulence
// displacement. Built from the pigment's transforms and warps in POV-Ray's order of application (pigment.cpp).
struct PatternStep {
  bool transformed = false;
  Matrix pattern_from_world;
  std::optional<Turbulence> turbulence;
  std::optional<RepeatWarp> repeat;
  std::optional<MappingWarp> mapping;
  std::optional<BlackHoleWarp> black_hole;
};

// An entry of the pigment's map: a colour, or a child pigment (index into RenderPigment::children).
struct RenderMapEntry {
  double value = 0;
  Colour colour;
  int child = -1;
};

// The entries a pattern value falls between (POV-Ray's Search_Blend_Map): at or above the last entry the last
// alone; otherwise the first entry not below the value (`cur`) and the one before it (`prev`; the same entry when
// the value equals an entry's or lies below the first), `fraction` of the way from prev to cur.
struct MapChoice {
  std::size_t prev = 0, cur = 0;
  double fraction = 0;
};
template <class Entry>   // any entry type with a `value`; the map is not empty
MapChoice choose_entries(const std::vector<Entry>& map, double value) {
  std::size_t cur = 0;
  if (value >= map.back().value) cur = map.size() - 1;
  else
    while (value > map[cur].value) ++cur;
  const std::size_t prev = (cur == 0 || value == map[cur].value || value >= map.back().value) ? cur : cur - 1;
  const double fraction = prev == cur ? 0.0 : (value - map[prev].value) / (map[cur].value - map[prev].value);
  return MapChoice{prev, cur, fraction};
}

struct RenderPigment {
  PatternKind pattern = PatternKind::solid;
  Colour colour;
  PatternParams params;
  WaveParams wave;
  std::vector<PatternStep> steps;        // world → pattern space, in order
  bool classic_turbulence_warps = false; // the classic turbulence displaces the point (not marble or wood)
  std::vector<RenderMapEntry> map;       // the written map or the pattern's built-in one; never empty for patterns
  std::vector<RenderPigment> children;   // pigment_map / pigment list entries; uv_mapping: its one pigment
  std::shared_ptr<const RenderImageMap> image;   // image_map
};

// A layer's normal perturbation (POV-Ray's Perturb_Normal, pattern/normal_perturbation.cpp). `pattern` carries the
// warps and transforms from world to pattern space and, for pattern normals, the pattern and its wave step.
struct RenderNormal {
  NormalKind kind = NormalKind::pattern;
  RenderPigment pattern;
  bool transformed = false;
  Matrix world_from_pattern;   // every transform of the normal composed (warps other than transforms left out)
  Matrix pattern_from_world;
  double amount = 0.5;
  double accuracy = 0.02;
  bool no_bump_scale = false;
  std::vector<SlopeEntry> slope_map;
  std::shared_ptr<const RenderImageMap> bump;    // bump_map
  bool use_index = false;                        // bump_map: heights from palette indices
  double facets_coords = 0, facets_size = 0.1, facets_metric = 2;   // facets
  std::shared_ptr<RenderNormal> uv_normal;       // uv_mapping: this normal at the hit's <u, v, 0>
  // normal_map, list-pattern normals or average's weighted normals (a null normal leaves the normal as it is).
  struct MapEntry {
    double value = 0;
    std::shared_ptr<const RenderNormal> normal;
  };
  std::vector<MapEntry> map;
};

// The wave sources that ripples and waves sum over (POV-Ray's Initialize_Waves, number_of_waves of them).
struct WaveSource {
  Vec3 centre;
  double frequency = 1;
};

struct RenderLayer {
  RenderPigment pigment;
  std::optional<RenderNormal> normal;
  Finish finish;
  double specular_exponent = 20;   // 1/roughness
  bool has_highlights = false;     // phong or specular non-zero
  bool reflects = false;           // some reflection colour is non-zero
  double reflection_exponent_inverse = 1;   // POV-Ray raises the reflected colour to 1/exponent
};

// A texture ready for shading (POV-Ray's TEXTURE): plain layers, or a pattern choosing or blending whole textures,
// each of them evaluated at this pattern's pattern-space point (Trace::ComputeOneTextureColour).
struct RenderTexture {
  double value = 0;                      // its entry value in the enclosing pattern's map
  std::vector<RenderLayer> layers;       // plain: top layer first (the last one written in the scene)
  RenderPigment pattern;                 // patterned: the pattern (checker, …, average, uv_mapping) and its steps
  std::vector<RenderTexture> children;   // patterned: the entries, ascending
  // The pattern's transforms composed: layer normals below are taken through them (POV-Ray's Warp_Normal over
  // the patterned textures passed on the way down).
  bool warps_normals = false;
  Matrix world_from_pattern, pattern_from_world;
  bool patterned() const { return !children.empty(); }
};

struct MediaSet;   // renderer/media/render_media.hpp

struct Material {
  RenderTexture texture;
  Interior interior;
  std::shared_ptr<const MediaSet> media;   // the interior's media ready for sampling (none without media)
  bool opaque = true;                // blocks shadow rays outright (pipeline §3 "opaque" flag)
  bool uv_mapping = false;           // the object's uv_mapping: textures at the hit's <u, v, 0>
  bool needs_uv = false;             // uv coordinates are read somewhere (uv_mapping of any kind)
  bool needs_surface = false;        // a slope or aoi pattern reads the surface's normal (TexturePoint::surface)
  ObjectPhotons photons;             // the object's photons { } flags (a CSG child's as its parent left them)
  // The photon target (index into RenderScene::photon_targets) whose tree the object is in; none: kNoPhotonTarget.
  std::uint32_t photon_target = ~0u;
  // The object's interior_texture as a material of its own (index into RenderScene::materials), shading the hits
  // seen from inside (Tracer::materials_facing); none: ~0u. `opaque` above is then true only if both are.
  std::uint32_t interior_material = ~0u;
  // Which lights light the object (POV-Ray's ComputeDiffuseLight): the scene's unless `no_global_lights`, then those
  // of its light groups (RenderLight::light.group), innermost group first.
  bool global_lights = true;
  std::vector<int> light_groups;
};
inline constexpr std::uint32_t kNoPhotonTarget = ~0u;

struct RenderLight {
  Light light;                       // as described (location, colour, kind, spot and fade parameters)
  Rgb colour;
  Vec3 parallel_direction;           // unit vector toward the light, for parallel lights
  Vec3 spot_axis;                    // unit axis location → point_at, for spotlights
  double cos_radius = 1, cos_falloff = 1;
  bool fades = false;
  // projected_through: the object its photons must leave through (photon_shoot.cpp); none without.
  std::shared_ptr<const PreparedObject> projected_through;
};

// The camera as its rays are made (renderer/camera.cpp): the non-planar projections keep unit vectors, the
// lengths they had and the aspect ratio POV-Ray derives from them.
struct RenderMeshCamera;   // renderer/mesh_camera.hpp
struct FocalBlurSetup;     // renderer/focal_blur.hpp

struct RenderCamera {
  Projection projection = Projection::perspective;
  Vec3 location, direction, up, right;
  double angle = 90, h_angle = 360, v_angle = 180;   // degrees
  double up_length = 1, right_length = 1, aspect = 1;
  // camera normal { }: bends each ray by the pattern at the ray's screen coordinates (with the scene's wave sources).
  std::shared_ptr<const RenderNormal> normal{};
  std::vector<WaveSource> normal_waves{};
  std::shared_ptr<const RenderMeshCamera> mesh{};   // projection mesh
  std::shared_ptr<const FocalBlurSetup> focal_blur{};   // aperture and blur_samples given (focal_blur.hpp)
};

// How working-space values become linear light for output (pipeline §6).
enum class GammaMode { power, legacy_srgb };

// Specialised paths chosen for this scene by what it holds (render_scene.cpp choose_specialisation). Each one
// gives the image the general path gives, bit for bit (tests/regression/same_image.cmake renders every reference
// scene both ways); BuildOptions::specialise turns each off, for those tests and for bench/specialisation_gain.py.
struct Specialisation {
  // Shadow rays ask the BVH for their nearest crossing first and walk every crossing only when that one lets
  // light through: POV-Ray's walk stops at its first crossing when that is opaque, so the crossings behind it
  // never matter then.
  bool nearest_shadow_first = false;
  // Nothing casts a shadow (every object no_shadow): no shadow ray is traced; the walk would find nothing.
  bool no_shadow_rays = false;
  // Meshes placed as objects of their own find their nearest hits through Embree (renderer/accel/embree_mesh.hpp)
  // instead of walking the own triangle BVH; hits inside CSG stay on the own BVH.
  bool embree_meshes = false;
};

// Which specialisations a build may use (all by default); names as --no-specialise takes them.
struct SpecialisationChoice {
  bool nearest_shadow_first = true;
  bool no_shadow_rays = true;
  bool embree_meshes = true;
  // Turns off the one named (false for an unknown name). "all" turns off every one.
  bool turn_off(std::string_view name);
  static std::string names();   // the names, comma-separated, for the usage text and errors
};

namespace photons { class PhotonMap; }   // renderer/photons/photon_map.hpp

// A photon target (POV-Ray shoots each light's photons at every target's bounding sphere; docs/issue20-photons.md
// §2): the first object with `target` on each path down the scene's object trees, its bounding sphere (POV-Ray's
// from its bounding box) and its flags.
struct PhotonTarget {
  Vec3 centre;
  double radius = 0;
  bool bounded = false;   // false: no finite box (nothing is shot at it)
  ObjectPhotons flags;
};

struct RenderScene {
  double scale = 1.0;
  Specialisation specialisation;   // the factor the scene was rescaled by for scale invariance (scene_scale.hpp), 1 if not
  Accelerator accelerator;
  std::vector<Material> materials;
  std::vector<RenderLight> lights;
  RenderCamera camera;
  // As parsed, except ambient_light, which is black when radiosity drops the `ambient` term (3.7 scenes, study §1.1).
  GlobalSettings settings;
  // Radiosity, when the scene has a radiosity block and the quality level computes it (+Q9); null otherwise.
  std::shared_ptr<const radiosity::RenderRadiosity> radiosity;
  // The background as POV-Ray keeps it after parsing (pipeline §5): 3.7 scenes without alpha output premultiply
  // rgb by 1 − t and clear f and t; with alpha output it stays as written. Older scenes clear f, and set t to 1
  // with alpha output, 0 without.
  Colour background_colour;
  bool output_alpha = false;         // camera rays may show the background's transparency
  std::vector<RenderPigment> sky_pigments;   // sky_sphere pigments in written order (evaluated last first)
  Rgb sky_emission{1, 1, 1};
  bool sky_transformed = false;
  Matrix sky_from_world;
  int language_version = 370;
  GammaMode gamma_mode = GammaMode::power;
  double assumed_gamma = 1.0;
  bool any_casts_shadow = false;     // no shadow rays at all when nothing casts one
  // Some object has no_image or no_reflection (or no_radiosity, with radiosity): rays carry their kind (geometry.hpp ray_kind); otherwise every ray
  // is traced as ray_kind::other and no object is skipped.
  bool any_ray_flags = false;
  bool any_shadow_fade = false;      // some transparent object has an interior fade that shadows apply
  std::vector<Fog> fogs;             // as POV-Ray lists them (the last written first)
  // Rainbows with a colour map (POV-Ray skips the others), the last written first, with their map built.
  struct RenderRainbow {
    Rainbow rainbow;
    RenderPigment colour_map;
  };
  std::vector<RenderRainbow> rainbows;
  std::shared_ptr<const MediaSet> atmosphere;   // top-level media (none without)
  bool any_interior_media = false;   // some interior has media: shadow rays track the interiors they cross
  NoiseGenerator noise_generator = NoiseGenerator::range_corrected;   // for turbulent fog
  std::vector<InteriorRef> camera_interiors;   // the interiors that contain the camera location
  std::vector<InteriorRef> containing_interiors(Vec3 point) const;
  std::vector<std::string> warnings; // approximations the build had to make, for the user to see
  std::vector<WaveSource> wave_sources;   // for ripples and waves normals
  // Photons (global_settings { photons { } }): the settings with the scene's limits filled in, the targets, and
  // the map shot when the scene was built (null when no photon was stored).
  std::optional<PhotonSettings> photon_settings;
  std::vector<PhotonTarget> photon_targets;
  std::shared_ptr<const photons::PhotonMap> photons;
};

struct BuildOptions {
  bool output_alpha = false;
  // POV-Ray's absolute tolerances at any scale, artefacts included: no rescaling of very small or very large
  // scenes (renderer/scene_scale.hpp), spheres kept in world units as POV-Ray keeps them
  // (with_world_space_spheres). POV-Ray's shadow cache is used always (tracer.cpp povray_shadow_walk).
  bool povray_tolerances = false;
  // The specialised paths the scene may use (Specialisation); those turned off take the general path, for tests
  // that prove the specialised ones change nothing and for measuring what each gains.
  SpecialisationChoice specialise;
  // Draft quality (+Q0…+Q5, Quality::quick_colours_at): every pigment with a quick_color becomes that solid colour,
  // wherever it is used (POV-Ray's Compute_Pigment returns the quick colour first). Objects keep the opacity of
  // their real pigments (POV-Ray's opaque flag is set by the parser).
  bool quick_colours = false;
  // The quality level (+Q): POV-Ray computes radiosity only at +Q9 and renders a radiosity scene as if it had no
  // radiosity block below that (study §7, checked with povray 3.7.0.10: +Q8 images are identical).
  int quality = 9;
  // Threads for the photon pass (0: every hardware thread). The map is the same for any count.
  int threads = 0;
};

RenderScene build_render_scene(const SceneDescription& scene, const BuildOptions& options);

}  // namespace povtrace::render
