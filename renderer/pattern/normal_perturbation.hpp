// Normal perturbation as POV-Ray 3.7 computes it (texture/normal.cpp Perturb_Normal, pattern/warps.cpp
// Warp_Normal/UnWarp_Normal): the normal is taken into pattern space, bent there, and taken back.
#pragma once

#include <vector>

#include "scene/description.hpp"
#include "renderer/render_scene.hpp"

namespace povtrace::render {

RenderNormal build_render_normal(const Normal& normal, ImageCache* images = nullptr);

// The scene's noise generator for the normal's pattern (and a uv-mapped normal's own).
void set_normal_generator(RenderNormal& normal, NoiseGenerator generator);

// POV-Ray's wave sources (Initialize_Waves): source i is the direction of the vector noise at (i, 0, 0), and its
// frequency comes from POV-Ray's 32-bit linear congruential generator seeded with −560851967. The directions
// follow povtrace's noise table, so they differ from POV-Ray's; the frequencies are POV-Ray's.
std::vector<WaveSource> make_wave_sources(int count);

// The layer normal (unit length) at a texture point: `normal` is the surface normal facing the ray.
Vec3 perturb_normal(const RenderNormal& n, Vec3 normal, const TexturePoint& at, const std::vector<WaveSource>& waves);
inline Vec3 perturb_normal(const RenderNormal& n, Vec3 normal, Vec3 world_point, const std::vector<WaveSource>& waves) {
  return perturb_normal(n, normal, TexturePoint(world_point), waves);
}

// POV-Ray's bump_map (support/imageutil.cpp): the heights (image grey, or palette indices with use_index) at the
// image position and at one pixel left-up and right-up of it span a triangle whose normal, taken into a frame
// around `normal` (x = normal × y), replaces it. Off an image used once the normal stays.
Vec3 bump_map_normal(const RenderImageMap& map, bool use_index, double amount, Vec3 pattern_point, Vec3 normal);

// The value of a pattern normal's pattern after its wave step and slope_map (what Perturb_Normal samples).
double slope_value(const RenderNormal& n, Vec3 pattern_point, const ShadingSurface* surface = nullptr);

}  // namespace povtrace::render
