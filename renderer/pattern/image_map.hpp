// Looking an image up at a pattern-space point, as POV-Ray 3.7's support/imageutil.cpp does (map_pos and the
// planar/spherical/cylindrical/torus mappers, image_colour_at with its interpolations).
//
// - Planar (map_type 0): x gives the column (the image spans 0 ≤ x < 1, repeated), y the row counted upwards;
//   z is ignored. Spherical (1): longitude from +x towards +z and latitude on the unit sphere. Cylindrical (2):
//   the angle around y and y itself. Torus (5): the angle around y and the angle around the tube of a torus of
//   major radius 1. `once` leaves the image off where x or y (planar, cylindrical y) lie outside [0, 1] or the
//   image position falls outside the image; off the image the colour is clear white (rgbt <1, 1, 1, 1>).
// - The position gets `offset` and 1e-10 added, and wraps into the image (rows counted from the top).
// - interpolate 2 (bilinear) and 4 (normalised distance, weights 1/d²) blend the four pixels around the position,
//   3 (bicubic) the sixteen around it with Catmull-Rom weights; accumulated in double, returned in single
//   precision. With `once` the neighbours are clamped to the image's edge, otherwise they wrap.
#pragma once

#include <array>
#include <memory>
#include <optional>

#include "scene/description.hpp"
#include "renderer/pattern/map_image.hpp"

namespace povtrace::render {

// What POV-Ray's ImageData holds besides the pixels.
struct ImageMapping {
  int map_type = 0;
  int interpolate = 0;
  bool once = false;
  int columns = 1, rows = 1;      // the image's size in pixels
  double width = 1, height = 1;   // columns and rows times `repeat`, in single precision
  double offset_u = 0, offset_v = 0;   // −offset · columns (rows)
};

ImageMapping image_mapping(const ImageMap& map, const MapImage& image);

// The continuous image position (column, row from the top) of a pattern-space point; nothing when off the image.
std::optional<std::array<double, 2>> image_position(const ImageMapping& m, Vec3 p);

// The (interpolated) pixel colour at an image position, and the palette index there (−1 for other images),
// interpolated and truncated as POV-Ray does (bump_map's use_index).
struct ImageSample {
  Texel colour;
  int index = -1;
};
ImageSample image_sample_at(const MapImage& image, const ImageMapping& m, double column, double row);
inline Texel image_colour_at(const MapImage& image, const ImageMapping& m, double column, double row) {
  return image_sample_at(image, m, column, row).colour;
}

// The colour an image_map pigment gives at a pattern-space point; none off the image (where the pigment is
// kOffImageColour, filtering nothing).
std::optional<Colour> image_map_colour(const MapImage& image, const ImageMapping& m, Vec3 p);
inline constexpr Colour kOffImageColour{1, 1, 1, 0, 1};   // clear white

struct RenderImageMap;
// POV-Ray's material_map (support/imageutil.cpp): off the image (`once`) the first texture; otherwise the palette
// index at the point, or for an image without a palette int(red · 255), taken modulo `count` when above it and
// then the last texture at most (POV-Ray walks its list of textures that far).
std::size_t material_map_index(const RenderImageMap& image, Vec3 pattern_point, std::size_t count);

// POV-Ray's image_pattern (support/imageutil.cpp): 0 off the image (`once`); else the colour's grey (0.297 R +
// 0.589 G + 0.114 B in single precision), or with use_alpha its transmit (red for an image without alpha), clipped to
// 0 … 1.
double image_pattern_value(const RenderImageMap& image, Vec3 pattern_point);

// An image_map pigment ready for lookups.
struct RenderImageMap {
  std::shared_ptr<const MapImage> image;
  ImageMapping mapping;
  bool use_alpha = false;   // image_pattern's use_alpha
  bool opaque = true;   // POV-Ray's HAS_FILTER clear: no `once`, no filter/transmit item, no clear pixel
};

}  // namespace povtrace::render
