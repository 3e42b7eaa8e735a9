// The contract between the parser and the renderer: a plain scene description. The parser fills it (with
// every POV-Ray 3.7 default already in the member initialisers), the renderer builds its own render-ready form
// from it. No renderer type appears here and nothing here computes anything but the values POV-Ray's parser
// itself resolves at parse time (camera vectors, transforms already composed into matrices).
#pragma once

#include <array>
#include <cstdint>
#include <deque>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "extent_box.hpp"
#include "mesh_description.hpp"
#include "radiosity_settings.hpp"
#include "sweep_description.hpp"
#include "source_location.hpp"
#include "text_description.hpp"
#include "vecmath.hpp"

namespace povtrace {

// Five-channel colour: rgb plus filter and transmit (povray-pixel-pipeline.md notation).
struct Colour {
  double r = 0, g = 0, b = 0, f = 0, t = 0;
  friend constexpr bool operator==(const Colour&, const Colour&) = default;
};

// A POV-Ray feature that povtrace parses but does not render yet (issue 3: standard include files and scenes
// must parse whole). A value built with one carries it; the parser refuses the value by this name, with both
// positions, when it reaches the rendered scene. A SceneDescription returned by the parser never holds one.
struct UnsupportedFeature {
  std::string name;   // e.g. "the pigment pattern 'granite'"
  SourceLoc loc;      // where the feature is written
};
using Unsupported = std::optional<UnsupportedFeature>;

// ---- Images (image_map, bump_map) -------------------------------------------------------------------------
// How an image's stored numbers become working-space values. POV-Ray decides it where the image is parsed
// (Parse_Image reads the file then), from the scene's gamma handling at that point (source/backend/parser/
// parstxtr.cpp Parse_Image; base/image/png.cpp Read).
enum class ImageGammaMode {
  none,              // no gamma handling yet (no assumed_gamma, no #version ≥ 3.7): the stored numbers as they are
  file_or_srgb,      // #version ≥ 3.7: the file's sRGB or gAMA chunk, else sRGB, re-encoded to the working gamma
  file_or_working,   // assumed_gamma in an older scene: the file's chunk, else the working gamma (no change)
};
struct ImageGamma {
  ImageGammaMode mode = ImageGammaMode::none;
  double working = 1.0;        // assumed_gamma at that point (1 when none was given yet)
  // `gamma G` / `gamma srgb` after the file name: the file is decoded with it whatever its chunks say.
  bool given = false;
  bool given_srgb = false;
  double given_gamma = 1.0;
  friend bool operator==(const ImageGamma&, const ImageGamma&) = default;
};

// `filter N, F` / `transmit N, T` (palette entry N, only for palette images) or `filter all F` / `transmit all T`
// (index −1), in written order: each `all` overwrites every palette entry written before it.
struct ImageChannelSetting {
  bool transmit = false;   // else filter
  int index = -1;          // −1: all
  double value = 0;
  SourceLoc loc;
};

// image_map { [png] "file" [gamma G] [map_type N] [once] [interpolate N] [filter/transmit …] [repeat] [offset] }
// and bump_map { … [bump_size F] [use_index|use_colour] }. The parser records the file's path; the renderer reads
// and decodes it (PNG only).
struct ImageMap {
  std::string file;          // the path found in the working directory or a library path, else as written
  SourceLoc file_loc;        // where the file name is written
  ImageGamma gamma;
  int map_type = 0;          // 0 planar, 1 spherical, 2 cylindrical, 5 torus
  int interpolate = 0;       // 0 none, 2 bilinear, 3 bicubic, 4 normalised distance
  bool once = false;
  bool use_index = false;    // bump_map: palette indices instead of the colours' grey
  bool use_alpha = false;    // image_pattern: the alpha (transmit) channel, or red without one, instead of the grey
  double repeat_u = 1, repeat_v = 1;   // `repeat <u, v>`: the image spans 1/u by 1/v units
  double offset_u = 0, offset_v = 0;   // `offset <u, v>` in image widths and heights
  std::vector<ImageChannelSetting> channels;
  bool has_filter = false;   // a filter or transmit item was written (POV-Ray's HAS_FILTER: not opaque)
};

// ---- Density files (density_file df3) -----------------------------------------------------------------
// A DF3 voxel grid as POV-Ray 3.7's Read_Density_File keeps it (source/backend/pattern/pattern.cpp): the parser
// reads the file where the pattern is written (runtime/density_file.hpp), the renderer looks voxels up. The voxels
// are kept as the file stores them (big-endian, `bytes_per_voxel` each, x fastest, then y, then z), so that a
// file of 8-bit voxels takes no more memory than on disk.
struct DensityGrid {
  std::size_t size_x = 0, size_y = 0, size_z = 0;
  int bytes_per_voxel = 1;            // 1, 2 or 4: decided by the file's length
  std::vector<std::uint8_t> voxels;   // size_x · size_y · size_z · bytes_per_voxel bytes
  std::string file;                   // the path it was read from
};

// ---- Textures -------------------------------------------------------------------------------------------
// Pigment patterns povtrace renders (povray-sdl-and-geometry.md §11). Any other pattern is refused by name.
namespace sdl {
struct FunctionValue;   // a compiled `function { … }` (function_value.hpp; evaluated by sdl::evaluate_function)
struct ObjectNotes;     // the parser's notes on an object it is building (parser/extents/object_notes.hpp)
}

enum class PatternKind {
  solid, checker, hexagon, brick,                                   // list patterns: entries 0, 1 (, 2)
  gradient, radial, onion, planar, boxed, spherical, cylindrical, leopard,
  bozo, spotted, granite, marble, wood, agate,                      // noise-based
  crackle, cells,                                                   // a random point or value per unit cube
  bumps, dents, wrinkles, ripples, waves,                           // the normal patterns used as pigments
  average,                                                          // mean of its pigment_map's pigments
  image_map,                                                        // the colour of an image (Pigment::image)
  image_pattern,                                                    // an image's grey or alpha (Pigment::image)
  function,                                                         // a user function of x, y, z (Pigment::function)
  spiral1, spiral2,                                                 // spirals around z with Pigment::arms arms
  quilted,                                                          // rounded cells (Pigment::control0/1)
  density_file,                                                     // a DF3 voxel grid (Pigment::density_file)
  uv_mapping,                                                       // its one entry at the hit's <u, v, 0>
  mandel, julia, magnet,                                            // escape-time fractals (Pigment::fractal)
  slope, aoi,                                                       // of the hit's normal (Pigment::slope) or the ray
  pigment_pattern,                                                  // the grey of a pigment (Pigment::pattern_pigment)
  object,                                                           // list: 1 inside Pigment::object, else 0
  material_map                                                      // textures only: an image's index picks one
};

// The shape the pattern value goes through after frequency and phase (POV-Ray's wave types).
enum class WaveType { ramp, triangle, sine, scallop, cubic, poly };

// Fractal turbulence: `turbulence V octaves N omega W lambda L`, defaults as POV-Ray's Create_Turb.
struct Turbulence {
  Vec3 amount;
  int octaves = 6;         // clamped to 1..10 by the parser, as POV-Ray does
  float omega = 0.5f;      // single precision, as POV-Ray keeps them (TURB's SNGL Lambda, Omega): the octave
  float lambda = 2.0f;     // sums then run in double from these rounded values
};

// `warp { turbulence … }` (POV-Ray's extra turbulence warp). `before` is the pattern transform written before
// this warp (and after the previous one): warps and transforms apply in the order they are written.
// `warp { repeat V [offset O] [flip F] }`: space cut into slabs of V's one non-zero component along its axis,
// each slab mapped onto the first, shifted by O per slab and, in odd slabs, mirrored on the axes F names.
struct RepeatWarp {
  int axis = 0;
  double width = 1;
  Vec3 offset{0, 0, 0};
  Vec3 flip{1, 1, 1};   // −1 on the flipped axes (POV-Ray stores them so)
};

// warp { planar | cylindrical | spherical | toroidal | cubic … } (POV-Ray's mapping warps): the point goes to the
// shape's own coordinates (angle, height or angle, distance), turned by the orientation.
enum class MappingWarpKind { planar, cylindrical, spherical, toroidal, cubic };
struct MappingWarp {
  MappingWarpKind kind = MappingWarpKind::cylindrical;
  Vec3 orientation{0, 0, 1};   // normalised as POV-Ray normalises (a zero vector gives NaN, as in POV-Ray)
  double dist_exp = 0;         // cylindrical, spherical, toroidal
  double major_radius = 1;     // toroidal
  double offset = 0;           // planar: the distance written after the orientation
};

// warp { black_hole <centre>, radius … }, with the centre and repeat vector as POV-Ray's Check_BH_Parameters
// leaves them.
struct BlackHoleWarp {
  Vec3 centre{0, 0, 0};
  double radius = 1, strength = 1, falloff = 2;
  bool inverse = false;
  int type = 0;                // only type 0 moves points
  bool repeat = false;
  Vec3 repeat_vector{0, 0, 0};
  bool uncertain = false;      // `turbulence` given: the centre jitters per repeated cell
  Vec3 uncertainty{0, 0, 0};
};

struct PatternWarp {
  Turbulence turbulence;
  std::optional<RepeatWarp> repeat;   // a repeat warp instead of a turbulence warp
  std::optional<MappingWarp> mapping; // or a mapping warp
  std::optional<BlackHoleWarp> black_hole;   // or a black hole
  Matrix before;
};

// crackle's parameters (Parse_Pattern's defaults): the value is form·(d1, d2, d3) of the distances to the three
// nearest cell points under `metric`, each with `offset` added; `solid` takes the nearest cell's noise instead.
struct CrackleParams {
  Vec3 form{-1, 1, 0};
  double metric = 2;
  double offset = 0;
  bool solid = false;
  friend bool operator==(const CrackleParams&, const CrackleParams&) = default;
};

// mandel, julia and magnet (POV-Ray's fractal patterns, Parse_Pattern's defaults): z iterated in the complex plane
// of the pattern's x, y; the value is the exterior colour of the iteration that escaped, or the interior colour.
struct FractalParams {
  int magnet = 0;                  // 0: mandel or julia; 1 or 2: `magnet 1` or `magnet 2`
  bool julia = false;              // julia form: z starts at the point and c is `coord`; mandel form: c is the point
  double coord_u = 0, coord_v = 0; // julia's c
  int iterations = 0;              // (int) of the float as written
  int exponent = 2;                // mandel and julia: 2…33
  int exterior_type = 1, interior_type = 0;
  double exterior_factor = 1, interior_factor = 1;
  friend bool operator==(const FractalParams&, const FractalParams&) = default;
};

// slope (Parse_Pattern's SLOPE_TOKEN): the angle between the hit's normal and `direction` (or, with point_at, the
// direction from the hit to the point), optionally mixed with the altitude of the point along `altitude`. Lengths
// are normalised as POV-Ray does: slope_weight + altitude_weight = 1.
struct SlopeParams {
  Vec3 direction{0, 1, 0};
  bool point_at = false;
  double slope_low = 0, slope_range = 0;         // `low, high` as low and high − low; range 0: not given
  Vec3 altitude{0, 0, 0};
  double altitude_low = 0, altitude_range = 0;
  double slope_weight = 1, altitude_weight = 0;
  int slope_axis = 0, altitude_axis = 0;         // ±(1 + axis) when the vector is exactly ± a unit axis, else 0
  friend bool operator==(const SlopeParams&, const SlopeParams&) = default;
};

struct Pigment;

// One entry of a colour map, pigment map or list pattern (checker, hexagon, brick). `value` is stored in single
// precision as POV-Ray's blend map entries are. An entry is a colour unless `pigment` is set.
struct MapEntry {
  double value = 0;
  Colour colour;
  std::shared_ptr<const Pigment> pigment;
};

struct Object;
struct Pigment {
  PatternKind pattern = PatternKind::solid;
  Colour colour;                 // solid colour (default: black, rgbft 0)
  // color_map, pigment_map or the list pattern's entries, ascending. Empty: the pattern's built-in map, which
  // POV-Ray picks only once the pigment is complete (texture/pigment.cpp Post_Pigment), so the renderer does.
  std::vector<MapEntry> entries;
  Vec3 gradient{1, 0, 0};        // gradient: the direction, normalised by the parser
  Vec3 brick_size{8, 3, 4.5};
  // POV-Ray keeps mortar, agate_turb, frequency, phase and exponent in single precision; so does the parser.
  double mortar = 0.5;           // brick: float(mortar − 2e-10), as POV-Ray stores it
  double agate_turb = 1.0;
  CrackleParams crackle;
  std::shared_ptr<const sdl::FunctionValue> function;   // the function pattern: a float function of x, y, z
  int arms = 0;                                         // spiral1/spiral2: the number of arms (a short in POV-Ray)
  float control0 = 1.0f, control1 = 1.0f;               // quilted's curve controls (single precision, as POV-Ray)
  double frequency = 1.0;        // 0 for list patterns: no frequency/phase/wave step (pattern.cpp Evaluate_TPat)
  double phase = 0.0;
  WaveType wave = WaveType::ramp;
  double exponent = 1.0;         // poly_wave
  std::optional<Turbulence> turbulence;   // the classic `turbulence` (always applied last, next to the pattern)
  std::vector<PatternWarp> warps;         // in written order
  Matrix world_from_pattern;     // every transform applied to the pigment since it was created (after its warps)
  std::shared_ptr<const ImageMap> image;   // image_map
  // density_file: the grid on the unit cube and `interpolate N` as POV-Ray stores it (an int; N % 10 picks 0
  // nearest voxel, 1 trilinear, anything else tricubic). Both are reset when density_file is written again.
  std::shared_ptr<const DensityGrid> density_file;
  int density_interpolation = 0;
  FractalParams fractal;         // mandel, julia, magnet
  SlopeParams slope;             // slope
  std::shared_ptr<const Pigment> pattern_pigment;   // pigment_pattern: the pigment whose grey is the value
  // object { OBJECT … }: the object whose inside picks the second entry, as declared (not moved with the pigment:
  // the pattern's transforms take the point to it).
  std::shared_ptr<const Object> object;
  // `noise_generator N` of this pattern (1…3); 0: the scene's (POV-Ray's GetNoiseGen).
  int noise_generator = 0;
  // quick_color: what the pigment shows instead in draft renders (+Q0…+Q5). POV-Ray uses it only when none of its
  // red, green, blue is -1 (its mark for "not given"), so such a colour is not kept.
  std::optional<Colour> quick_colour;
  SourceLoc loc;
  Unsupported unsupported;
};

// Finish defaults for #version 3.7 (povray-pixel-pipeline.md §2).
struct Finish {
  Colour ambient{0.1f, 0.1f, 0.1f};   // a colour, so single precision as in POV-Ray
  Colour emission{};
  double diffuse = 0.6;
  double diffuse_back = 0.0;     // second `diffuse` value
  // The two diffuse values before this finish block's `albedo` rescaling: POV-Ray's radiosity term uses these
  // (RawDiffuse, RawDiffuseBack; issue19-study §1.1), light sources the rescaled ones. Every finish block sets them
  // from the values it holds at its end, so a finish copied from an identifier keeps that finish's rescaled values
  // as its raw ones unless `diffuse` is written again (as in POV-Ray's Parse_Finish).
  double diffuse_raw = 0.6;
  double diffuse_back_raw = 0.0;
  double brilliance = 1.0;
  double phong = 0.0;
  double phong_size = 40.0;
  double specular = 0.0;
  double roughness = 0.05;       // as written; the shading exponent is 1/roughness
  double metallic = 0.0;
  Colour reflection_min{}, reflection_max{};   // single precision, filter/transmit unused
  double reflection_falloff = 1.0;
  double reflection_exponent = 1.0;   // as written (`exponent E`); POV-Ray raises the reflected colour to 1/E
  bool reflection_fresnel = false;
  double reflection_metallic = 0.0;
  bool conserve_energy = false;
  double crand = 0.0;
  // irid { amount thickness T turbulence V }: thin-film interference on the light a layer reflects, single precision as
  // POV-Ray keeps them (its turbulence is V's x).
  double irid = 0.0, irid_thickness = 0.0, irid_turbulence = 0.0;
  // Pre-3.1 finish items that POV-Ray moves into the object's interior when the object is placed (Post_Process):
  // `ior` (when given) and `refraction` (always, default 1: it scales what is seen through the object).
  std::optional<double> legacy_ior;
  std::optional<double> legacy_caustics;   // pre-3.1 `caustics` in finish: moved to the interior as written
  double legacy_refraction = 1.0;
  SourceLoc loc;
  Unsupported unsupported;
};

// normal { } (POV-Ray's TNORMAL, texture/normal.cpp Perturb_Normal). The normal-only patterns perturb the normal
// with their own formula; any pigment pattern used as a normal (`pattern`) is sampled around the point and its
// slope bends the normal.
enum class NormalKind { pattern, bumps, dents, wrinkles, ripples, waves, quilted,
                        facets,        // the nearest random cube point replaces the normal (Normal::facets_*)
                        bump_map,      // the slope of an image's grey (or palette indices): pattern.image
                        uv_mapping,    // uv_normal at the hit's <u, v, 0>
                        average };     // the weighted mean of the map's normals

// A slope_map entry `[value, <height, slope>]` (single precision, as POV-Ray's blend map entries).
struct SlopeEntry {
  double value = 0, height = 0, slope = 0;
};

struct Normal;

// An entry of a normal_map, of a list pattern's normals (checker, hexagon, brick: values 0, 1, 2) or of an average
// (its weight): the value, single precision as POV-Ray's blend map entries, and its normal.
struct NormalMapEntry {
  double value = 0;
  std::shared_ptr<const Normal> normal;
};

struct Normal {
  NormalKind kind = NormalKind::pattern;
  // The pattern and what it shares with pigments: pattern kind and parameters (for `pattern`), frequency, phase,
  // wave type, turbulence, warps and transforms (for every kind). Its colour and entries are unused.
  Pigment pattern;
  bool has_type = false;         // POV-Ray's "No normal type given" otherwise
  double amount = 0.5;           // the float after the pattern, or bump_size
  double accuracy = 0.02;        // the sampling distance of pattern normals (POV-Ray's Delta)
  bool no_bump_scale = false;
  std::vector<SlopeEntry> slope_map;
  // facets [coords C] [size S] [metric M]: POV-Ray's defaults (coords 0: facets by the normal's direction).
  double facets_coords = 0.0, facets_size = 0.1, facets_metric = 2.0;
  std::shared_ptr<const Normal> uv_normal;   // uv_mapping: the normal evaluated at the hit's uv
  // normal_map, list-pattern normals or average's entries, ascending (average: in written order). When set, the
  // pattern picks or blends these normals and this normal's own amount is unused (POV-Ray's Perturb_Normal).
  std::vector<NormalMapEntry> map;
  SourceLoc loc;
  Unsupported unsupported;
};

struct TextureLayer {
  Pigment pigment;
  Finish finish;
  // none: the layer uses the surface's own normal. Shared and immutable (copied when a transform changes it), so
  // that copying a texture for every transformed object does not copy its normals.
  std::shared_ptr<const Normal> normal;
};

struct Texture;

// One texture of a patterned texture's map or list; `value` in single precision, as POV-Ray's blend map entries.
struct TextureMapEntry {
  double value = 0;
  std::shared_ptr<const Texture> texture;
};

// A patterned texture (POV-Ray's Parse_Texture falling through to Parse_Pattern): whole textures chosen or
// blended by a pattern — `texture { PATTERN texture_map { [v TEXTURE_BODY] … } }`, `texture { checker|hexagon|brick
// texture { … } … }`, `tiles { … tile2 … }` (a checker), `average` (weighted mean), or `uv_mapping TEXTURE_BODY`
// (its one texture at the hit's <u, v, 0>). Each texture is evaluated at the pattern-space point of this one.
struct TexturePattern {
  Pigment pattern;                        // pattern kind, parameters, wave, turbulence, warps, transforms
  std::vector<TextureMapEntry> entries;   // ascending
};

// Plain: layers in written order, the *last* one the top layer (pipeline §2 "Layers"). Patterned: `pattern` set
// and no layers (POV-Ray refuses to layer a patterned texture or to layer over one).
struct Texture {
  std::vector<TextureLayer> layers;
  std::shared_ptr<const TexturePattern> pattern;
  SourceLoc loc;
  Unsupported unsupported;
  bool patterned() const { return pattern != nullptr; }
};

// media { … } (POV-Ray's Parse_Media, interior/media.cpp): absorption, emission and scattering per unit length,
// scaled by the product of its densities, integrated along a ray segment by POV-Ray's sampling methods. The
// defaults are #version 3.5+'s (method 3, 1 interval, 10 samples); older scenes get method 1, 10 intervals and
// 1 sample, as in POV-Ray. Colours are single precision like POV-Ray's RGBColour.
struct Media {
  int method = 3;
  int intervals = 1;
  int min_samples = 10, max_samples = 10;
  double confidence = 0.9;
  double variance = 1.0 / 128.0;
  double ratio = 0.9;
  double jitter = 0.0;
  double aa_threshold = 0.1;
  int aa_level = 3;
  Colour absorption, emission, scattering;   // rgb only
  int scattering_type = 1;   // 1 isotropic, 2 Mie hazy, 3 Mie murky, 4 Rayleigh, 5 Henyey-Greenstein
  double eccentricity = 0.0;
  double extinction = 1.0;   // how much scattering takes out of the ray (POV-Ray's sc_ext)
  bool collect = true;       // photons: `collect off` ignores them
  // density { … } blocks in written order; the density at a point is the product of their colours. Each is a
  // pigment whose maps are density maps (a density_map's entries are densities).
  std::vector<Pigment> densities;
  SourceLoc loc;
  Unsupported unsupported;   // a density uses something povtrace does not render yet
};

struct Interior {
  double ior = 1.0;
  double fade_distance = 0.0;
  double fade_power = 0.0;
  Colour fade_colour{};          // single precision, filter/transmit unused
  double refraction = 1.0;       // legacy `refraction`: scales the light seen through the object
  // Fake caustics (POV-Ray's Caustics: `caustics C` stores 45·C): light crossing the surface toward a light is
  // brightened by 1 + |N·L|^caustics, N the layer's normal.
  double caustics = 0.0;
  bool hollow = false;           // the object's `hollow` flag (POV-Ray keeps it on the interior): fog and media
                                 // reach rays inside hollow objects only
  // media { } blocks in written order (shared: copies of an interior share them until a transform moves them).
  std::shared_ptr<const std::vector<Media>> media;
  // Which media list this is, kept by copies and by transformed or rescaled copies: the interiors CSG children
  // inherit from their parent stay one interior for the renderer (same_interior) however often they moved.
  std::uint64_t media_id = 0;
  Unsupported unsupported;
};

// ---- Geometry -------------------------------------------------------------------------------------------
// `ellipsoid` is POV-Ray's Do_Ellipsoid (shape/spheres.cpp Sphere::Scale, Sphere::Transform): set once a
// non-uniform scale, a matrix or a transform block reaches the sphere. Until then POV-Ray moves the centre and
// scales the radius itself, so its tolerances apply in world units (what --povray-tolerances reproduces).
struct Sphere {
  Vec3 centre;
  double radius = 1;
  bool ellipsoid = false;
};
// Normal as written (unit-normalised by the parser).
struct Plane {
  Vec3 normal{0, 1, 0};
  double distance = 0;
};
// Corners sorted per axis by the parser. As in POV-Ray (shape/boxes.cpp Box::Translate, Box::Scale), translations
// and scalings move the corners themselves (re-sorted) until a rotation, matrix or transform block gives the box a
// transform (`rotated`); the object's matrix holds only the transforms from then on. uv_mapping sees the difference.
struct Box {
  Vec3 corner1{-1, -1, -1}, corner2{1, 1, 1};
  bool rotated = false;
};

// The parser turns a difference into an intersection with its later children inverted, as POV-Ray does;
// `difference` remains for descriptions built in code.
enum class CsgKind { union_, merge, intersection, difference };
struct Object;
struct Light;
struct Csg {
  CsgKind kind = CsgKind::union_;
  std::vector<Object> children;
  std::vector<Light> lights;      // light sources written inside the CSG move with it
  // POV-Ray's INVERTED_FLAG on the CSG node, toggled by each inversion (which also turns the kind and the children):
  // an intersection leaves inverted children out of its bounding box (CSG::Compute_BBox).
  bool inverted = false;
  // light_group { objects… light_source { }… [global_lights B] }: a union whose lights light only its objects (and
  // not at all without objects); the parser gives each placed group its id (Light::group, Object::light_groups).
  bool light_group = false;
};

// The quadric-like shapes, as written (POV-Ray's canonical transforms are the renderer's business). The parser has
// already refused the degenerate ones POV-Ray refuses (cylinder/cone with coincident end points).
struct Cylinder { Vec3 end1, end2{0, 1, 0}; double radius = 1; bool open = false; };
struct Cone { Vec3 end1; double radius1 = 1; Vec3 end2{0, 1, 0}; double radius2 = 0; bool open = false; };
struct Disc { Vec3 centre; Vec3 normal{0, 0, 1}; double radius = 1, hole_radius = 0; };   // normal unit length
struct Torus { double major = 0, minor = 0; bool sturm = false; };

// poly { N, <c…> }, cubic { <c…> } (N = 3), quartic { <c…> } (N = 4): the surface Σ c·xⁱyʲzᵏ = 0 over i + j + k ≤ N,
// coefficients in POV-Ray's term order (x's power from N down, then y's, then z's). Shared: 35 or more numbers.
struct Poly {
  int order = 4;
  std::shared_ptr<const std::vector<double>> coefficients;
  bool sturm = false;
  // The inverse of the object's transform as POV-Ray composes it (each transform's own inverse, multiplied in
  // reverse order): far from the surface the ray's polynomial has huge coefficients whose last bits decide which
  // roots the Sturm solver finds, so inverting the composed matrix instead would change pixels.
  Matrix object_from_world{};
};

// quadric { <A,B,C>, <D,E,F>, <G,H,I>, J }: A x² + B y² + C z² + D xy + E xz + F yz + G x + H y + I z + J = 0.
struct Quadric { Vec3 square{1, 1, 1}, mixed, linear; double constant = 1; };

// superellipsoid { <e, n> }: (|x|^(2/e) + |y|^(2/e))^(e/n) + |z|^(2/n) = 1, exponents as written.
struct Superellipsoid { double e = 1, n = 1; };

// ovus { BOTTOM, TOP }: a sphere of radius BOTTOM at the origin and one of radius TOP at <0, BOTTOM, 0>, joined by
// a spindle of a torus tangent to both (POV-Ray 3.7's ovus; the parser turns TOP >= 2·BOTTOM into a sphere).
struct Ovus {
  double bottom_radius = 1, top_radius = 1;
  bool sturm = false;   // the spindle's quartic solved with Sturm sequences
};

// height_field { png "file" [smooth] [water_level W] }: the image file's path (located by the parser, read by the
// renderer); water_level as a fraction of the full height.
struct HeightField {
  std::string file;
  SourceLoc file_loc;
  // `function W, H { … }`: the samples POV-Ray's parser makes of a float function (row-major, z = 0 first), or the
  // pigment of a pigment function, which the renderer samples (it evaluates patterns), instead of a file.
  std::shared_ptr<const std::vector<std::uint16_t>> samples;
  std::shared_ptr<const Pigment> pigment_function;
  int noise_generator = 2;       // the scene's when the function was parsed (POV-Ray samples it then)
  int samples_width = 0, samples_depth = 0;
  bool smooth = false;
  double water_level = 0;
};

// One blob component as POV-Ray's parser leaves it: a sphere keeps its centre and squared radius through
// translations, rotations and uniform scalings; any other transform makes it an ellipsoid (centre and radius in its
// own space, placed by `transform`). A cylinder runs from `centre` (its base) to `apex`, then `transform`.
enum class BlobComponentKind { sphere, ellipsoid, cylinder };
struct BlobComponent {
  BlobComponentKind kind = BlobComponentKind::sphere;
  Vec3 centre, apex;
  double radius2 = 0;
  double strength = 0;
  Matrix transform;   // the component's own transforms (ellipsoid, cylinder)
};
// blob { threshold T components… [sturm] }: the components in written order, shared by copies of the object.
struct Blob {
  double threshold = 1;
  bool sturm = false;
  std::shared_ptr<const std::vector<BlobComponent>> components;
  // Each component's own texture (`sphere { … texture { … } }`), moved by the component's transforms after it and by
  // the blob's; null where the component has none (the blob's texture shades its share). Empty when no component
  // has one. POV-Ray blends the textures of the components whose field reaches a point by those fields.
  std::vector<std::shared_ptr<const Texture>> textures;
};

// isosurface { function { F } [contained_by { box { C1, C2 } | sphere { C, R } }] [threshold T] [accuracy A]
// [max_gradient G] [max_trace N | all_intersections] [open] }: the surface F(x, y, z) = T inside its container, with
// POV-Ray's defaults and its corrections of out-of-range values already applied by the parser.
struct Isosurface {
  std::shared_ptr<const sdl::FunctionValue> function;   // a float function of x, y, z that povtrace can evaluate
  bool sphere_container = false;
  Vec3 corner1{-1, -1, -1}, corner2{1, 1, 1};   // box container, sorted per axis
  Vec3 centre;                                  // sphere container
  double radius = 1;
  double threshold = 0;
  double accuracy = 0.001;
  double max_gradient = 1.1;
  int max_trace = 1;
  bool open = false;
  // evaluate P0, P1, P2: max_gradient adapts along each ray (lowered to G·P2 when above P0 at each root search,
  // raised to g·P1² where a piece's slope g exceeds G / P1), starting from max_gradient at every ray.
  bool evaluate = false;
  std::array<double, 3> evaluate_params{0, 0, 0};
};

// julia_fractal { <c> [quaternion|hypercomplex] [FUNCTION] [max_iteration N] [precision P] [slice <S>, D] }: the 4-D
// julia set of z ← f(z) + c cut by the hyperplane S·(x, y, z, w) = D (POV-Ray 3.7's Fractal), as the parser leaves
// it: defaults, clamps and the algebra/function check done.
enum class JuliaAlgebra : std::uint8_t { quaternion, hypercomplex };
enum class JuliaFunction : std::uint8_t {
  sqr, cube, reciprocal, exp, ln, sin, asin, cos, acos, tan, atan, sinh, asinh, cosh, acosh, tanh, atanh, pwr
};
struct JuliaFractal {
  std::array<double, 4> julia{1, 0, 0, 0};
  JuliaAlgebra algebra = JuliaAlgebra::quaternion;
  JuliaFunction function = JuliaFunction::sqr;
  std::array<double, 2> exponent{0, 0};     // pwr(x, y)
  int max_iteration = 20;                   // at least 1
  double precision = 1.0 / 20.0;            // the march step: 1 / the SDL precision (which is at least 1)
  std::array<double, 4> slice{0, 0, 0, 1};  // normalised
  double slice_distance = 0;
  // The inverse of the object's transform as POV-Ray composes it (Compose_Transforms: each transform's own inverse,
  // exact for translate, rotate and scale, multiplied in reverse order): the fractal's chaotic surface shows the last
  // bit of the object-space ray, which inverting the composed matrix would change.
  Matrix object_from_world{};
};

// bicubic_patch { type T [flatness F] [u_steps U] [v_steps V] [uv_vectors …] P1 … P16 }: a Bézier patch whose 16
// control points are kept where the object's transforms have put them (POV-Ray keeps no matrix for a patch and
// subdivides it in the scene's space), row by row: points[4·i + j] is P[i][j], u along i, v along j.
struct BicubicPatch {
  int type = 1;                             // 0 or 1: the same surface (POV-Ray subdivides per ray or once)
  double flatness = 0;
  int u_steps = 0, v_steps = 0;
  std::array<Vec3, 16> points{};
  std::array<std::array<double, 2>, 4> uv_vectors{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}};
};

using Shape = std::variant<Sphere, Plane, Box, Csg, Cylinder, Cone, Disc, Torus, Poly, Triangle, Polygon, Mesh, Quadric,
                           Superellipsoid, Ovus, HeightField, Blob, Text, Lathe, Prism, Sor, Isosurface, JuliaFractal,
                           BicubicPatch>;

// POV-Ray's bounding box of an object placed in the scene (what min_extent()/max_extent() give then), made by the
// parser when it places the object (parser/extents/); the renderer culls the object's rays with it (csg_build.cpp).
struct PlacedBox {
  bool known = false;   // false: the parser could not make it (a height field's samples without the renderer's geometry)
  ExtentBox box;        // the box as placed; POV-Ray's huge box culls nothing
  // The box a later uniform scaling by a power of two carries (renderer/scene_scale.cpp), so that the scaled box is
  // the one POV-Ray's Transform would give: a carried box itself; for the shapes whose box is remade from the shape,
  // that box without the narrowing by clip objects (a transform drops it) — a clipped poly's, its first clip's.
  // Unset when the remade box is the huge box whatever the transform (a plane, a poly without clips).
  std::optional<ExtentBox> moved;
};

// photons { … } on an object (POV-Ray's PH_* object flags, parse.cpp; issue20-photons.md): a photon target is shot
// at by every light whose flags and the object's allow refraction or reflection; `collect off` keeps photons off
// its surface; a pass_through object lets photons on their way to a target cross it unchanged. A CSG parent's
// flags reach its children (POV-Ray's Post_Process).
struct ObjectPhotons {
  double target = 0;                   // > 0: a target, its spacing multiplier (`target [F]`, 1 by default)
  std::optional<bool> refraction;      // `refraction on|off`: unset is neither (the light's setting decides)
  std::optional<bool> reflection;
  bool collect = true;
  bool pass_through = false;
  bool operator==(const ObjectPhotons&) const = default;
};

struct Object {
  Shape shape;
  Matrix world_from_object;                 // composed object transforms in written order
  // Never null once the parser has placed the object. A texture that no transform can change how it renders
  // (texture_ignores_transforms) is not moved with the object, so copies of one declared object share it.
  std::shared_ptr<const Texture> texture;
  // interior_texture { … }: shades the surface where a ray meets it from inside (the raw normal, after `inverse`,
  // pointing along the ray: POV-Ray's Interior_Texture). Moves with the object as `texture` does; CSG children
  // without one take their parent's.
  std::shared_ptr<const Texture> interior_texture;
  std::optional<Interior> interior;
  // double_illuminate [bool]: lights on the far side of the surface light it too (POV-Ray skips its
  // light-behind-the-surface test, DOUBLE_ILLUMINATE_FLAG). Set on a CSG, it is set on the whole tree.
  bool double_illuminate = false;
  // The light groups whose lights light this object (POV-Ray's LLights: its own group's, and those of groups around it
  // unless a nearer group has lights and objects of its own), and whether the scene's
  // lights do too (a light_group's `global_lights`, off by default, set on every object of the group).
  std::vector<int> light_groups;
  bool no_global_lights = false;
  bool inverse = false;                     // leaves only: inverting a CSG inverts its children (De Morgan)
  bool no_shadow = false;
  // no_image [bool], no_reflection [bool] (POV-Ray's NO_IMAGE_FLAG, NO_REFLECTION_FLAG): the object is left out by
  // rays that see the image (camera rays, and rays refracted without a reflection in their history), or by rays
  // with a reflection in their history. Shadow rays see it either way. A CSG parent's flags reach its children
  // (post_process); the renderer decides per ray kind (renderer/geometry.hpp, ray_kind).
  bool no_image = false;
  bool no_reflection = false;
  // no_radiosity [bool]: POV-Ray leaves the object out of radiosity sample rays (and the rays traced from them)
  // only; the renderer tests it through ray_flag::no_radiosity where it renders radiosity.
  bool no_radiosity = false;
  // radiosity { importance F }, F in (0, 1]: the share of a gathering's sample rays that may stop at this object
  // (issue19-study §1). Unset on an object that did not write it: the renderer then uses the scene's
  // SceneDescription::radiosity_default_importance (POV-Ray reads that default when rendering). CSG children that did
  // not write it are given their parent's, or the #default in force when the top-level object was placed.
  std::optional<double> radiosity_importance;
  // uv_mapping (before any texture): textures are evaluated at the hit's <u, v, 0> and later transforms of the
  // object no longer move them (POV-Ray's UV_FLAG). CSG children that inherit the texture inherit the flag.
  bool uv_mapping = false;
  std::optional<bool> hollow;               // unset: inherited from a CSG parent, else false
  ObjectPhotons photons;
  SourceLoc loc;
  Unsupported unsupported;
  std::vector<Object> clipped_by;           // the surface and inside are limited to inside all of these
  std::vector<Object> bounded_by;           // rays missing one of these (and starting outside) skip the object
  bool clips_are_bounds = false;            // one list for both (clipped_by { bounded_by } or the reverse)
  // Bounds POV-Ray removed when the object was placed ("Unnecessary bounding object removed"): no longer tested,
  // but the bounding box they gave the object stays, and rays that miss that box miss the object (see
  // renderer/csg_build.cpp).
  std::vector<Object> removed_bounds;
  // What the parser keeps on the object while building it (parser/extents/object_notes.hpp: the state of POV-Ray's
  // bounding box of the object), opaque here: the renderer never reads it. Shared by copies, and dropped when the
  // object is placed, so always null in a SceneDescription returned by the parser.
  std::shared_ptr<const sdl::ObjectNotes> parser_notes;
  // Made when the object is placed in the scene, for the objects the renderer culls by it: CSG (and the children of
  // a union without clip or bounding objects, which are placed one by one) and objects with clip, bounding or
  // removed bounding objects. Unset for other shapes, which the renderer bounds by their own bounds, for clip and
  // bound objects, and for objects built in code (the renderer then culls by the clip objects' box).
  std::optional<PlacedBox> placed_box;
};

// ---- Camera and lights ----------------------------------------------------------------------------------
// POV-Ray 3.7's camera types (mesh_camera is refused by name).
enum class Projection {
  perspective, orthographic, fisheye, ultra_wide_angle, omnimax, panoramic, spherical,
  cylinder1, cylinder2, cylinder3, cylinder4,  // `cylinder N`: 1, 2 vertical/horizontal axis, 3, 4 the same, orthographic
  mesh                                         // mesh_camera: rays leave the faces of meshes (Camera::mesh)
};

// One mesh of a mesh_camera: its triangles (shared with any other placement of the same mesh) and its transforms.
struct MeshCameraMesh {
  std::shared_ptr<const MeshData> data;
  Matrix world_from_object;
  bool transformed = false;
};

// mesh_camera { RAYS DISTRIBUTION [MAX_DISTANCE] mesh { … }… [smooth] } (POV-Ray 3.7's experimental mesh camera;
// docs/issue21-mesh-camera.md): which face each pixel's rays leave from (distribution 0: mesh r for ray r;
// 1: the meshes one after another; 2: side by side; 3: by the first mesh's uv map), along the face normal.
struct MeshCamera {
  unsigned rays_per_pixel = 1;
  unsigned distribution = 0;
  double max_distance = 0;   // primary rays see only hits nearer than this (0: no limit)
  bool smooth = false;       // distribution 3: the smooth_triangle normals interpolated
  std::vector<MeshCameraMesh> meshes;
};

// Final camera vectors, resolved by the parser in POV-Ray's fixed order (pipeline §1).
// Focal blur (camera aperture, blur_samples, confidence, variance, focal_point), POV-Ray 3.7's defaults. On when
// aperture ≠ 0 and blur_samples > 0 (POV-Ray's useFocalBlur).
struct FocalBlur {
  double aperture = 0.0;
  int samples = 0;            // blur_samples' maximum
  int min_samples = 0;        // blur_samples MIN, MAX: the confidence test starts after MIN samples
  double confidence = 0.9;
  double variance = 1.0 / 10000.0;
  // The distance to the plane in focus: |focal_point − location| (before the camera's transforms), else the
  // direction's length as angle or look_at made it (1 without either; 1 also for a distance of 0). Negative
  // until the camera is resolved.
  double focal_distance = -1.0;
};

struct Camera {
  Projection projection = Projection::perspective;
  Vec3 location{0, 0, 0};
  Vec3 direction{0, 0, 1};
  Vec3 up{0, 1, 0};
  Vec3 right{1.33, 0, 0};
  double angle = 90;                         // degrees: the field of view of the non-planar projections
  double h_angle = 360, v_angle = 180;       // spherical: horizontal and vertical field of view
  // normal { … }: bends every camera ray, the pattern read at the ray's screen coordinates <x0, y0, 0>
  // (POV-Ray's CreateCameraRay: the projection's own x0, y0 after its last change).
  std::shared_ptr<const Normal> normal;
  std::shared_ptr<const MeshCamera> mesh;    // projection mesh
  FocalBlur focal_blur;
  SourceLoc loc;
  Unsupported unsupported;
};

struct Light {
  Vec3 location;
  Colour colour{1, 1, 1};
  bool parallel = false;
  bool spotlight = false;
  bool cylinder = false;    // a spotlight with parallel beams (POV-Ray's cylindrical light)
  bool shadowless = false;
  Vec3 point_at{0, 0, 1};
  double radius = 30.0;     // spotlight: degrees; cylinder: distance from the axis (0.75 by default)
  double falloff = 45.0;    // spotlight: degrees; cylinder: distance from the axis (1 by default)
  double tightness = 0.0;   // spotlight
  double fade_distance = 0.0;
  double fade_power = 0.0;
  // area_light axis1, axis2, size1, size2 (pipeline §3): a grid of size1 × size2 point samples spanning the axes
  // around `location`, used for the shadow test only.
  bool area = false;
  Vec3 axis1, axis2;
  int size1 = 1, size2 = 1;
  int adaptive = 100;       // POV-Ray's default: subdivide the grid down to single cells
  bool jitter = false;
  bool circular = false;
  bool orient = false;
  bool media_interaction = true;    // the light scatters in media
  bool media_attenuation = false;   // media (and fog) between it and a point dim it
  // photons { refraction on|off reflection on|off area_light }: whether it shoots photons at targets (with the
  // target's flags: either one `on` and neither `off`), and from every cell of its area light.
  std::optional<bool> photon_refraction, photon_reflection;
  bool photon_area_light = false;
  // looks_like { object }: an object placed at the light (moved with it), casting no shadow; the parser places it in
  // the scene next to the light. At most one.
  std::vector<Object> looks_like;
  // projected_through { object }: photons from this light leave only through this object, starting beyond its last
  // crossing (POV-Ray 3.7 uses it nowhere else). Moved by the light's later transforms; texture and interior
  // removed, as POV-Ray removes them. At most one.
  std::vector<Object> projected_through;
  // The light_group this light belongs to (it lights only that group's objects), or -1 for a scene light.
  int group = -1;
  SourceLoc loc;
  Unsupported unsupported;
};

// sky_sphere { pigment { … } … [emission C] transforms } (pipeline §5): pigments evaluated at the ray direction
// of a miss, last written first; the transforms turn the direction (inverted, as a point — POV-Ray's behaviour,
// so a translate shifts it too).
struct SkySphere {
  std::vector<Pigment> pigments;
  Colour emission{1, 1, 1};
  Matrix world_from_sky;
  SourceLoc loc;
  Unsupported unsupported;
};

// fog { … } (POV-Ray's Parse_Fog): constant fog (type 1) or ground fog (type 2) thinning out above `offset` along
// `up` with the scale `alt`; `distance` is where the fog reaches 1 − 1/e; `turbulence` varies its density.
struct Fog {
  int type = 1;
  double distance = 0;      // 0: the fog has no effect
  Colour colour;            // filter and transmit: the fog tints / lets through part of what is behind it
  double alt = 0, offset = 0;
  Vec3 up{0, 1, 0};         // unit length; turned by the fog's transforms
  std::optional<Turbulence> turbulence;
  double turb_depth = 0.5;
  SourceLoc loc;
};

// rainbow { angle A width W distance D direction <V> up <U> jitter J arc_angle R falloff_angle F colour_map { … } }
// as POV-Ray's Parse_Rainbow leaves it: `angle` lowered by half the width and both in radians; direction, up and
// right unit length and square to each other; arc and falloff halved into radians, except that an angle not written
// keeps POV-Ray's default 180 as it stands (so the arc never cuts a rainbow without arc_angle, and falloff_angle
// alone fades over 180 − F·π/360: POV-Ray's units, kept). The colour map is read through a gradient x pattern.
struct Rainbow {
  double angle = 0, width = 0;
  double distance = 1e7;          // POV-Ray's MAX_DISTANCE
  double jitter = 0;
  Vec3 antisolar, up{0, 1, 0}, right{1, 0, 0};
  double arc_angle = 180, falloff_angle = 180, falloff_width = 0;
  std::optional<Pigment> colour_map;   // absent: the rainbow shows nothing (POV-Ray skips it)
  SourceLoc loc;
};

// ---- Whole scene ----------------------------------------------------------------------------------------
struct GlobalSettings {
  std::optional<double> assumed_gamma;   // absent: 1.0 for #version ≥ 3.7, legacy sRGB otherwise (pipeline §6)
  Colour ambient_light{1, 1, 1};
  int max_trace_level = 5;
  double adc_bailout = 1.0 / 255.0;
  std::optional<int> noise_generator;    // 1, 2 or 3; absent: 1 before #version 3.5, 2 from then on (as POV-Ray)
  int number_of_waves = 10;              // the wave sources ripples and waves normals sum over
  // irid_wavelength: the wavelengths irid uses for red, green and blue, in micrometres (POV-Ray 3.7's defaults
  // 0.70, 0.52, 0.48, Scene's constructor; single precision).
  Colour irid_wavelength{0.70f, 0.52f, 0.48f};
};

// global_settings { photons { … } } (POV-Ray's ScenePhotonSettings, parse.cpp; issue20-photons.md): the photon map's
// spacing (or a count it is derived from), how photons are gathered, and the tracing limits of the photon pass.
struct PhotonSettings {
  double spacing = 1.0;              // world distance between photons at a target (times its multiplier)
  int count = 0;                     // > 0: spacing is derived from an estimate of the photons it gives
  int gather_min = 20, gather_max = 100;
  double expand_tolerance = 0.2;     // expand_thresholds: how much the density may change when the radius grows
  int expand_min = 35;               // … and below how many photons it grows anyway
  double jitter = 0.4;
  double autostop = 0.5;             // fraction of a target's angular radius after which a missed ring stops
  std::optional<int> max_trace_level;     // unset: the scene's
  std::optional<double> adc_bailout;      // unset: the scene's
  double radius = -1, radius_multiplier = 1;   // gather radius (≤ 0: estimated from the map) and its factor
  double media_radius = -1, media_radius_multiplier = 1;
  int media_steps = 0;               // always 0: `media N` (media photons) is refused by name
  double media_spacing_factor = 1.0;
  // load_file "F" (the map is read from F instead of shot) or save_file "F" (written to F once shot), in POV-Ray's
  // file layout; at most one of them (the last written wins, as in POV-Ray).
  std::string load_file, save_file;
  SourceLoc file_loc;                // where that file was named
  SourceLoc loc;                     // the photons keyword
};

struct SceneDescription {
  // The file names the locations of everything in the description point to (source_location.hpp).
  std::shared_ptr<const FileNames> file_names;
  int language_version = 370;            // round(100 · #version); 370 when no #version was seen
  bool version_given = false;            // a #version directive appeared before the first statement
  // Any #version directive, or a version given by +MV/Version= (POV-Ray's languageVersionSet).
  bool language_version_set = false;
  // POV-Ray's EffectiveLanguageVersion: the version when one was set, else 3.62 — a scene without any #version is
  // treated as a legacy scene where POV-Ray asks for it (the ambient term below, among others).
  int effective_language_version() const { return language_version_set ? language_version : 362; }
  GlobalSettings settings;
  // global_settings { radiosity { … } } (issue19-study §1): present when the scene writes such a block, which is
  // POV-Ray's "radiosity enabled" (blocks in several global_settings edit the same settings). POV-Ray computes
  // radiosity only at +Q9 and above; where it does, a layer's `ambient · ambient_light` term is dropped when
  // effective_language_version() ≥ 370 and kept for older scenes, and `emission` is always added (§1.1, trace.cpp).
  // Below +Q9 the renderer renders the scene as without this block, as POV-Ray does; at +Q9 it refuses it at
  // `radiosity->loc` until the pretrace exists (issue 19 step 7; the evaluator is renderer/radiosity/gather.hpp).
  std::optional<RadiositySettings> radiosity;
  // #default { radiosity { importance F } } as it stands at the end of the parse: the importance of every object
  // whose radiosity_importance is unset (POV-Ray's defaultImportance, read when rendering). 1.0 unless written.
  double radiosity_default_importance = 1.0;
  // global_settings { photons { … } } with a positive gather maximum (POV-Ray's photonsEnabled); absent otherwise.
  std::optional<PhotonSettings> photons;
  Camera camera;
  Colour background{0, 0, 0, 0, 1};      // POV-Ray 3.7's default: rgbt <0,0,0,1>
  std::optional<SkySphere> sky_sphere;
  std::vector<Fog> fogs;                 // in POV-Ray's list order: the last one written first
  std::vector<Rainbow> rainbows;         // the same: the last one written first
  std::vector<Media> atmosphere;         // top-level media { } blocks in written order
  std::vector<Light> lights;
  // Every object has a texture after parsing (CSG inheritance and the #default texture resolved as POV-Ray's
  // Post_Process does). A deque, not a vector: a scene of 100,000 objects grows without moving the ones already
  // placed (a vector's regrowth touched twice the list's memory, a third of the parse time of such a scene).
  std::deque<Object> objects;
};

}  // namespace povtrace
