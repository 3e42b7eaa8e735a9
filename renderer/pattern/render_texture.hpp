// Builds the render-ready texture (RenderTexture, render_scene.hpp) from a described one: plain layers, or a
// patterned texture's pattern and its textures.
#pragma once

#include "scene/description.hpp"
#include "renderer/render_scene.hpp"

namespace povtrace::render {

// `quick_colours`: draft quality, layer pigments with a quick_color are that colour (build_render_pigment).
RenderTexture build_render_texture(const Texture& texture, ImageCache& images, bool quick_colours = false);

// POV-Ray's Test_Opacity: some layer of a plain texture has a pigment without filter or transmit anywhere. A
// patterned texture is never opaque (its textures are looked at point by point).
bool texture_is_opaque(const RenderTexture& texture);

// Whether shading the texture reads the hit's uv coordinates (a uv_mapping pigment, normal or texture in it).
bool texture_reads_uv(const RenderTexture& texture);
// Whether any pattern in it is slope or aoi, which read the surface's normal (TexturePoint::surface).
bool texture_reads_surface(const RenderTexture& texture);

// The value a patterned texture's pattern gives at the pattern-space point `p`, which picks or blends its textures
// (choose_entries): the pattern's value through its wave, or for a material_map the index of the texture its
// image picks (material_map_index).
double texture_pattern_value(const RenderTexture& texture, const TexturePoint& p);

// The scene's noise generator for every pigment and normal pattern of the texture.
void set_texture_generator(RenderTexture& texture, NoiseGenerator generator);

}  // namespace povtrace::render
