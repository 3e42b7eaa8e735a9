// Builds the render-ready pigment (RenderPigment, render_scene.hpp) from a described one.
#pragma once

#include <vector>

#include "scene/description.hpp"
#include "renderer/render_scene.hpp"

namespace povtrace::render {

// Image maps read their file through `images` (one decoding per file and settings) or, without one, on their own.
// With `quick_colours` (draft quality, BuildOptions::quick_colours) the pigment, or each pigment in its maps, that
// has a quick_color is that solid colour instead.
RenderPigment build_render_pigment(const Pigment& pigment, ImageCache* images = nullptr, bool quick_colours = false);

// An image map (or bump map) ready for lookups; read through `images` when given.
std::shared_ptr<const RenderImageMap> build_render_image(const ImageMap& map, ImageCache* images);

// Whether any colour the pigment can produce has filter or transmit (POV-Ray's Post_Pigment HAS_FILTER): its own
// colour, its map's colours, its child pigments, and image maps used once, with a filter/transmit item or with
// clear pixels.
bool pigment_has_transparency(const RenderPigment& pigment);

// The noise generator of the scene (POV-Ray: 1 before #version 3.5, 2 from then on) for every pigment.
void use_noise_generator(std::vector<Material>& materials, NoiseGenerator generator);
// The same for one pigment and the pigments of its maps (a sky_sphere's), its function patterns included.
void set_generator(RenderPigment& r, NoiseGenerator generator);
// Only the generator its function patterns' functions read (PatternParams::function_noise_generator): the scene's,
// where the pigment's own patterns use another.
void set_function_generator(RenderPigment& r, int generator);

}  // namespace povtrace::render
