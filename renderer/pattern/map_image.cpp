#include "renderer/pattern/map_image.hpp"

#include <cmath>
#include <cstdio>
#include <optional>
#include <stdexcept>

#include "renderer/located_error.hpp"

namespace povtrace::render {

namespace {
// A transfer curve of POV-Ray's colourspace.cpp, in single precision: sRGB, or a power law by its encoding
// exponent (decode x^(1/e), encode x^e); exponent 1 is neutral.
struct Curve {
  bool srgb = false;
  float encoding = 1.0f;
};

float curve_decode(Curve c, float x) {
  if (c.srgb) return x < 0.04045f ? x / 12.92f : std::pow((x + 0.055f) / 1.055f, 2.4f);
  if (c.encoding == 1.0f) return x;
  return std::pow(std::max(x, 0.0f), 1.0f / c.encoding);
}

float curve_encode(Curve c, float x) {
  if (c.srgb) return x <= 0.0031308f ? x * 12.92f : 1.055f * std::pow(x, 1.0f / 2.4f) - 0.055f;
  if (c.encoding == 1.0f) return x;
  return std::pow(std::max(x, 0.0f), c.encoding);
}

Curve power_by_decoding(double g) { return Curve{false, static_cast<float>(1.0 / g)}; }

// The curve the file's values are decoded with (png.cpp Read); none when gamma handling is off.
std::optional<Curve> file_curve(const image::PngSamples& png, const ImageGamma& gamma) {
  if (gamma.given) return gamma.given_srgb ? Curve{true, 1.0f} : power_by_decoding(gamma.given_gamma);
  if (gamma.mode == ImageGammaMode::none) return std::nullopt;
  if (png.srgb_chunk) return Curve{true, 1.0f};
  if (png.file_gamma) return Curve{false, static_cast<float>(*png.file_gamma)};
  if (gamma.mode == ImageGammaMode::file_or_srgb) return Curve{true, 1.0f};
  return std::nullopt;   // the working gamma both ways: POV-Ray's transcoding curve is neutral
}

// What Image::Create's grey table and Gray8 storage make of a decoded grey: the grey mix, times 255, truncated.
float stored_low_grey(float g) {
  const float mixed = g * 0.297f + g * 0.589f + g * 0.114f;
  return static_cast<float>(static_cast<unsigned char>(mixed * 255.0f)) / 255.0f;
}

Texel opaque(float r, float g, float b) { return Texel{r, g, b, 0.0f, 0.0f}; }

MapImage palette_image(const image::PngSamples& png, const ImageGamma& gamma) {
  MapImage out;
  out.indexed = true;
  out.width = png.width;
  out.height = png.height;
  for (std::size_t i = 0; i < png.palette.size(); ++i) {
    const auto& e = png.palette[i];
    Texel t = opaque(decode_sample(png, gamma, e[0], 255), decode_sample(png, gamma, e[1], 255),
                     decode_sample(png, gamma, e[2], 255));
    if (i < png.palette_alpha.size()) t.t = 1.0f - static_cast<float>(png.palette_alpha[i]) / 255.0f;
    out.palette.push_back(t);
  }
  for (int y = 0; y < png.height; ++y)
    for (int x = 0; x < png.width; ++x) {
      const std::uint16_t index = png.sample(x, y, 0);
      if (index >= out.palette.size()) throw std::invalid_argument("a pixel's palette index lies beyond the palette");
      out.indices.push_back(static_cast<std::uint8_t>(index));
      out.texels.push_back(out.palette[index]);
    }
  return out;
}

Texel direct_texel(const image::PngSamples& png, const ImageGamma& gamma, int x, int y) {
  const unsigned max = (1u << png.bit_depth) - 1u;
  const bool colour = png.colour_type == 2 || png.colour_type == 6;
  const bool alpha = png.colour_type == 4 || png.colour_type == 6;
  const float r = decode_sample(png, gamma, png.sample(x, y, 0), max);
  Texel t = colour ? opaque(r, decode_sample(png, gamma, png.sample(x, y, 1), max),
                            decode_sample(png, gamma, png.sample(x, y, 2), max))
                   : opaque(r, r, r);
  if (png.colour_type == 0 && png.bit_depth <= 8) t = opaque(stored_low_grey(r), stored_low_grey(r), stored_low_grey(r));
  if (alpha)
    t.t = 1.0f - static_cast<float>(png.sample(x, y, colour ? 3 : 1)) / static_cast<float>(max);
  return t;
}
}  // namespace

float decode_sample(const image::PngSamples& png, const ImageGamma& gamma, unsigned s, unsigned max) {
  const float x = static_cast<float>(s) / static_cast<float>(max);
  const std::optional<Curve> file = file_curve(png, gamma);
  if (!file) return x;
  const float linear = curve_decode(*file, x);
  return gamma.working == 1.0 ? linear : curve_encode(power_by_decoding(gamma.working), linear);
}

MapImage decode_map_image(const image::PngSamples& png, const ImageGamma& gamma) {
  if (png.colour_type == 3) {
    MapImage out = palette_image(png, gamma);
    out.alpha_channel = !png.palette_alpha.empty();
    return out;
  }
  if (png.colour_type == 0 && png.has_trns)
    throw std::invalid_argument("a grey PNG with a tRNS chunk is not read by povtrace (use an alpha channel)");
  MapImage out;
  out.width = png.width;
  out.height = png.height;
  out.alpha_channel = png.colour_type == 4 || png.colour_type == 6;
  for (int y = 0; y < png.height; ++y)
    for (int x = 0; x < png.width; ++x) out.texels.push_back(direct_texel(png, gamma, x, y));
  return out;
}

void apply_channel_settings(MapImage& image, const std::vector<ImageChannelSetting>& settings) {
  double all_filter = 0, all_transmit = 0;   // other images: the last `all` of each channel, added to every pixel
  for (const ImageChannelSetting& s : settings) {
    const std::string word = s.transmit ? "transmit" : "filter";
    if (!image.indexed && s.index >= 0)
      fail_at_scene(s.loc, "'" + word + "' with a palette entry cannot be used with a non color-mapped image "
                           "(as in POV-Ray)");
    if (!image.indexed) {
      (s.transmit ? all_transmit : all_filter) = s.value;
      continue;
    }
    if (s.index >= static_cast<int>(image.palette.size()))
      fail_at_scene(s.loc, word + " color register value out of range: the palette has " +
                               std::to_string(image.palette.size()) + " entries (as in POV-Ray)");
    const auto value = static_cast<float>(s.value);
    for (std::size_t i = 0; i < image.palette.size(); ++i)
      if (s.index < 0 || static_cast<std::size_t>(s.index) == i) (s.transmit ? image.palette[i].t : image.palette[i].f) = value;
  }
  for (std::size_t i = 0; i < image.texels.size(); ++i) {
    Texel& t = image.texels[i];
    if (image.indexed) {
      t = image.palette[image.indices[i]];
    } else {
      t.f = static_cast<float>(static_cast<double>(t.f) + all_filter);
      t.t = static_cast<float>(static_cast<double>(t.t) + all_transmit);
    }
    image.transparent = image.transparent || t.t > 0.0f;
  }
}

namespace {
std::string exact(double v) {
  char text[40];
  std::snprintf(text, sizeof text, "%a ", v);
  return text;
}

// Everything the decoded image depends on, numbers written exactly.
std::string cache_key(const ImageMap& m) {
  std::string key = m.file + '\n' + exact(static_cast<int>(m.gamma.mode)) + exact(m.gamma.working) +
                    exact(m.gamma.given) + exact(m.gamma.given_srgb) + exact(m.gamma.given_gamma);
  for (const auto& s : m.channels) key += '\n' + exact(s.transmit) + exact(s.index) + exact(s.value);
  return key;
}
}  // namespace

std::shared_ptr<const MapImage> load_map_image(const ImageMap& map) {
  image::PngSamples png;
  try {
    png = image::read_png_samples(map.file);
  } catch (const std::exception& e) {
    fail_at_scene(map.file_loc, "cannot read the image '" + map.file + "': " + e.what());
  }
  MapImage decoded;
  try {
    decoded = decode_map_image(png, map.gamma);
  } catch (const std::invalid_argument& e) {
    fail_at_scene(map.file_loc, "unsupported: the image '" + map.file + "': " + e.what());
  }
  apply_channel_settings(decoded, map.channels);
  return std::make_shared<const MapImage>(std::move(decoded));
}

std::shared_ptr<const MapImage> ImageCache::load(const ImageMap& map) {
  auto& slot = images_[cache_key(map)];
  if (!slot) slot = load_map_image(map);
  return slot;
}

}  // namespace povtrace::render
