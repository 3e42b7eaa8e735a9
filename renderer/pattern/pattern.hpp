// Pattern values in pattern space and the wave step after them, as POV-Ray 3.7 computes them
// (pattern.cpp: Evaluate_TPat and the *_pattern functions; povray-sdl-and-geometry.md §11).
#pragma once

#include <optional>

#include "scene/description.hpp"
#include "scene/object_geometry.hpp"
#include "runtime/noise.hpp"

namespace povtrace::render {

struct RenderPigment;

// What a pattern function reads besides the point.
struct RenderImageMap;   // image_map.hpp

struct PatternParams {
  PatternKind kind = PatternKind::solid;
  Vec3 gradient{1, 0, 0};
  Vec3 brick_size{8, 3, 4.5};
  double mortar = 0.5;
  double agate_turb = 1.0;
  CrackleParams crackle;
  std::optional<Turbulence> turbulence;   // the classic turbulence: marble, wood and agate use it inside
  NoiseGenerator noise_generator = NoiseGenerator::range_corrected;
  double frequency = 1.0, phase = 0.0;    // ripples and waves use them inside too (as well as in the wave step)
  std::shared_ptr<const sdl::FunctionValue> function;   // the function pattern
  int arms = 0;                                          // spiral1, spiral2
  double control0 = 1.0, control1 = 1.0;                 // quilted
  // The scene's noise generator as the function pattern's function reads it (f_noise3d): set with noise_generator
  // (set_generator), but the scene's own where a pigment's patterns use another (sky_sphere, height fields).
  int function_noise_generator = 2;
  std::shared_ptr<const DensityGrid> density_file;   // density_file: the voxel grid
  int density_interpolation = 0;                     // and `interpolate N` as written
  FractalParams fractal;                             // mandel, julia, magnet
  SlopeParams slope;                                 // slope
  // pigment_pattern: the pigment whose grey is the value (owned: set_generator copies it before changing it).
  std::shared_ptr<RenderPigment> pigment;
  // The pattern's own `noise_generator` (1…3), 0 for the scene's: set_generator keeps it (POV-Ray's GetNoiseGen).
  int own_noise_generator = 0;
  // object: its inside test, made from the description (kept to make it again for the scene's noise generator,
  // which an isosurface in it reads).
  std::shared_ptr<const PreparedObject> object;
  std::shared_ptr<const Object> object_description;
  std::shared_ptr<const RenderImageMap> image;   // image_pattern: the image read raw, its mapping
};

// What slope and aoi read of the surface being shaded, in world space: the hit point, the normal as POV-Ray's
// PNormal (facing the ray, perturbed by the layers' normals so far) and the ray's direction. Patterns evaluated
// away from a surface (media densities, functions) have none and give 0, as in POV-Ray.
struct ShadingSurface {
  Vec3 point;
  Vec3 normal;
  Vec3 ray_direction;
};

// The frequency/phase/wave step every pattern value goes through.
struct WaveParams {
  double frequency = 1.0;
  double phase = 0.0;
  WaveType wave = WaveType::ramp;
  double exponent = 1.0;
};

// The raw value of the pattern at a pattern-space point: 0..1 for most, 0/1 for checker and brick, 0/1/2 for
// hexagon, any value for marble and wood (their wave folds it).
double pattern_value(const PatternParams& params, Vec3 p, const ShadingSurface* hit = nullptr);

// pigment_pattern's value: the pigment's grey at p, in single precision as POV-Ray's Colour::greyscale; 0 where
// no colour is found (off an image map used once). Defined with the pigments (renderer/pigment.cpp).
double pigment_grey(const RenderPigment& pigment, Vec3 p, const ShadingSurface* surface);

// Frequency, phase and the wave shape (Evaluate_TPat after the pattern switch).
double apply_wave(double value, const WaveParams& wave);

// quilted's vector (the pattern is the mean of its absolute components; the normal adds it times the amount).
Vec3 quilted_offset(Vec3 p, double control0, double control1);

// POV-Ray's cycloidal(): sin(2π·v) computed on the fractional part of v.
double cycloidal(double v);

}  // namespace povtrace::render
