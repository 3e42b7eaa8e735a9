// The image of an image_map or bump_map as POV-Ray 3.7 holds it after reading the file: single-precision
// r, g, b, filter, transmit per pixel in the scene's working gamma, with the image_map's filter/transmit settings
// applied, plus the palette index of each pixel for palette images.
//
// Facts reproduced (source/base/image/png.cpp Read, image.cpp, encoding.cpp, colourspace.cpp; support/
// imageutil.cpp no_interpolation; parser/parstxtr.cpp Parse_Image, Parse_Image_Map; 3.7-stable):
// - The decoding curve: `gamma G`/`gamma srgb` after the file name when given; otherwise, with gamma handling on,
//   the file's sRGB chunk (sRGB), else its gAMA chunk (a power law), else sRGB (3.7 scenes) or the working gamma
//   itself (older scenes with assumed_gamma: no change). The decoded value is re-encoded into the working gamma
//   (assumed_gamma). Without gamma handling the stored numbers are used as they are. All in single precision.
// - Stored value v of maximum m (2^bits − 1) reads as decode(v / m); alpha (never gamma-decoded) as a / m and gives
//   filter 0, transmit 1 − alpha. RGB tRNS colour keys are ignored.
// - Palette images keep a decoded colour table (alpha from the tRNS chunk) and each pixel's index.
// - Grey images of up to 8 bits go through a colour table too, but are stored back as 8-bit greys: the decoded
//   value's grey mix 0.297 + 0.589 + 0.114 in single precision, times 255, truncated.
// - `filter all F` / `transmit all T` on a palette image overwrite that channel of every table entry; `filter N, F`
//   / `transmit N, T` one entry (N < the palette's size; palette images only). On other images the last `all`
//   value is added to every pixel's channel.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "scene/description.hpp"
#include "renderer/image/png_samples.hpp"

namespace povtrace::render {

struct Texel {
  float r = 0, g = 0, b = 0, f = 0, t = 0;
};

struct MapImage {
  int width = 0;
  int height = 0;
  std::vector<Texel> texels;             // row-major, top row first
  std::vector<std::uint8_t> indices;     // palette images: each pixel's palette index
  std::vector<Texel> palette;            // palette images: the decoded table
  bool indexed = false;
  bool transparent = false;              // some pixel has transmit (POV-Ray's !IsOpaque)
  bool alpha_channel = false;            // the file has alpha (or a palette with tRNS): POV-Ray's HasTransparency
  const Texel& at(int x, int y) const {
    return texels[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)];
  }
  std::uint8_t index_at(int x, int y) const {
    return indices[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)];
  }
};

// The value POV-Ray's curve chain gives a stored sample s of maximum `max` under `gamma` and the file's chunks.
// Exposed for tests.
float decode_sample(const image::PngSamples& png, const ImageGamma& gamma, unsigned s, unsigned max);

// The image as POV-Ray stores it, before any filter/transmit setting. Throws std::invalid_argument for layouts
// povtrace refuses (grey images with a tRNS chunk, palette indices beyond the palette).
MapImage decode_map_image(const image::PngSamples& png, const ImageGamma& gamma);

// Applies the image_map's filter/transmit settings; errors (a palette entry setting on another image, an entry
// beyond the palette) are located at the setting.
void apply_channel_settings(MapImage& image, const std::vector<ImageChannelSetting>& settings);

// Reads and decodes the file of `map` (PNG only), with its settings applied. A missing, unreadable or refused file
// is a located error at the file name.
std::shared_ptr<const MapImage> load_map_image(const ImageMap& map);

// The images of one scene build: a file read under the same gamma and settings is decoded once, however many
// pigments name it.
class ImageCache {
 public:
  std::shared_ptr<const MapImage> load(const ImageMap& map);

 private:
  std::map<std::string, std::shared_ptr<const MapImage>> images_;
};

}  // namespace povtrace::render
