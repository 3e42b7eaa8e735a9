// Reads a height field's PNG image into POV-Ray's 16-bit height samples and builds its primitive. Facts from POV-Ray
// 3.7 (source/backend/shape/hfield.cpp Compute_HField, smooth_height_field; support/imageutil.cpp
// image_height_at; base/image/png.cpp and image.cpp, 3.7-stable):
// - Sample (x, z) is the image pixel (x, height − 1 − z): the image's bottom row is z = 0.
// - Heights are unsigned 16-bit, from the values as stored (no gamma): a grey PNG of up to 8 bits goes through
//   POV-Ray's grey chain (value / max as a float, the grey mix 0.297 + 0.589 + 0.114 of three equal channels in
//   float, truncated to 8 bits, then · 65535 / 255 in float, truncated); a 16-bit grey PNG gives
//   float(v) / 65535 · 65535 truncated; an 8-bit RGB PNG gives (r·256 + g)·255 with r, g = value / 255 (red the
//   high byte, green the low one); a 16-bit RGB PNG gives the grey mix 0.297r + 0.589g + 0.114b · 65535.
//   A palette PNG gives its palette index · 256 (POV-Ray keeps 256, not 257, for compatibility: the top index
//   gives 65280). Images with alpha are refused by name.
// - The object space is the sample grid: x in [0, w − 1], z in [0, h − 1], y the raw 16-bit height; POV-Ray places
//   it by the scaling <1/(w − 1), 1/65536, 1/(h − 1)> before the object's own transforms.
// - The bounding box in y is [max(min height, 65536·water_level) − 0.001, max height + 0.001].
// - `smooth` vertex normals: at each sample the sum of the unit normals (turned upwards) of the four triangles
//   fanned around it towards its 4-neighbours that exist, normalised and stored as 16-bit integers 32767·n.
#include <cmath>
#include <fstream>

#include "runtime/image_files.hpp"
#include "renderer/located_error.hpp"
#include "renderer/image/image.hpp"
#include "renderer/image/png_io.hpp"
#include "renderer/image/png_samples.hpp"
#include "renderer/shapes/height_field.hpp"
#include "renderer/shapes/solid_shapes.hpp"
#include "renderer/pattern/render_pigment.hpp"
#include "renderer/tracer.hpp"

namespace povtrace::render {

namespace {
constexpr double hfield_offset = 0.001;   // hfield.cpp HFIELD_OFFSET

[[noreturn]] void fail_at(const SourceLoc& at, const std::string& message) { fail_at_scene(at, message); }

struct PngKind {
  int bit_depth = 0;
  int colour_type = 0;   // PNG's: 0 grey, 2 RGB, 3 palette, 4 grey + alpha, 6 RGBA
};

// The IHDR chunk's bit depth and colour type (bytes 24 and 25 of every PNG file).
PngKind png_kind(const std::string& file, const SourceLoc& at) {
  std::ifstream in(file, std::ios::binary);
  char header[26] = {};
  if (!in.read(header, sizeof header))
    fail_at(at, "cannot read the height_field image '" + file + "' (no such file, or not a PNG image)");
  return PngKind{static_cast<unsigned char>(header[24]), static_cast<unsigned char>(header[25])};
}

std::uint16_t grey_low_depth(int index, int max) {
  const float g = static_cast<float>(index) / static_cast<float>(max);
  const float mixed = g * 0.297f + g * 0.589f + g * 0.114f;
  const auto stored = static_cast<unsigned char>(mixed * 255.0f);
  return static_cast<std::uint16_t>(static_cast<float>(stored) / 255.0f * 65535.0f);
}

std::uint16_t height_of(const PngKind& kind, const float* rgba) {
  const int max = (1 << kind.bit_depth) - 1;
  const auto stored = [&](int c) { return static_cast<int>(std::lround(rgba[c] * static_cast<double>(max))); };
  if (kind.colour_type == 0 && kind.bit_depth <= 8) return grey_low_depth(stored(0), max);
  if (kind.colour_type == 0) return static_cast<std::uint16_t>(static_cast<float>(stored(0)) / 65535.0f * 65535.0f);
  const float r = static_cast<float>(stored(0)) / static_cast<float>(max);
  const float g = static_cast<float>(stored(1)) / static_cast<float>(max);
  const float b = static_cast<float>(stored(2)) / static_cast<float>(max);
  if (kind.bit_depth <= 8) return static_cast<std::uint16_t>((r * 256.0 + g) * 255.0);
  return static_cast<std::uint16_t>((0.297 * r + 0.589 * g + 0.114 * b) * 65535.0f);
}

// add_single_normal: the unit normal of the triangle (x0,z0) (x1,z1) (x2,z2), turned upwards, added to n.
int add_triangle_normal(const HeightFieldData& d, int x0, int z0, int x1, int z1, int x2, int z2, Vec3& n) {
  const int xs = d.width - 1, zs = d.depth - 1;
  for (const int v : {x0, x1, x2})
    if (v < 0 || v > xs) return 0;
  for (const int v : {z0, z1, z2})
    if (v < 0 || v > zs) return 0;
  const Vec3 v0{double(x0), d.height(x0, z0), double(z0)}, v1{double(x1), d.height(x1, z1), double(z1)},
      v2{double(x2), d.height(x2, z2), double(z2)};
  Vec3 t = cross(v2 - v0, v1 - v0);
  const double len = length(t);
  t = std::abs(len) > tolerance::epsilon ? t / len : Vec3{0, 1, 0};
  if (t.y < 0.0) t = -t;
  n += t;
  return 1;
}

void smooth_normals(HeightFieldData& d) {
  d.normals.resize(d.heights.size());
  for (int z = 0; z < d.depth; ++z)
    for (int x = 0; x < d.width; ++x) {
      Vec3 n{};
      add_triangle_normal(d, x, z, x + 1, z, x, z + 1, n);
      add_triangle_normal(d, x, z, x, z + 1, x - 1, z, n);
      add_triangle_normal(d, x, z, x - 1, z, x, z - 1, n);
      add_triangle_normal(d, x, z, x, z - 1, x + 1, z, n);
      const double len = length(n);
      n = std::abs(len) > tolerance::epsilon ? n / len : Vec3{0, 1, 0};
      d.normals[static_cast<std::size_t>(z) * d.width + x] = {static_cast<std::int16_t>(32767 * n.x),
                                                              static_cast<std::int16_t>(32767 * n.y),
                                                              static_cast<std::int16_t>(32767 * n.z)};
    }
}

// A palette PNG's heights: the index of each pixel, · 256 (image_height_at's indexed case).
std::vector<std::uint16_t> palette_heights(const HeightField& h, int& width, int& height) {
  image::PngSamples png;
  try {
    png = image::read_png_samples(h.file);
  } catch (const image::ImageError& e) {
    fail_at(h.file_loc, "cannot read the height_field image '" + h.file + "': " + e.what());
  }
  width = png.width;
  height = png.height;
  std::vector<std::uint16_t> heights(static_cast<std::size_t>(width) * height);
  for (int z = 0; z < height; ++z)
    for (int x = 0; x < width; ++x)
      heights[static_cast<std::size_t>(z) * width + x] = static_cast<std::uint16_t>(png.sample(x, height - 1 - z, 0) * 256);
  return heights;
}

// A JPEG file (its first two bytes): POV-Ray reads it with libjpeg as an 8-bit RGB image, whose heights are those of
// an 8-bit RGB PNG (image_height_at: red the high byte, green the low one).
bool is_jpeg_file(const std::string& file) {
  std::ifstream in(file, std::ios::binary);
  unsigned char head[2] = {};
  return in.read(reinterpret_cast<char*>(head), 2) && head[0] == 0xFF && head[1] == 0xD8;
}

std::shared_ptr<HeightFieldData> read_height_field(const HeightField& h) {
  if (h.samples)   // function W, H { … }, sampled by the parser
    return height_field_data(*h.samples, h.samples_width, h.samples_depth, h.water_level, h.smooth);
  const bool jpeg = is_jpeg_file(h.file);
  const PngKind kind = jpeg ? PngKind{8, 2} : png_kind(h.file, h.file_loc);
  if (kind.colour_type == 3) {
    int width = 0, height = 0;
    std::vector<std::uint16_t> heights = palette_heights(h, width, height);
    if (width < 2 || height < 2)
      fail_at(h.file_loc, "the height_field image '" + h.file + "' needs at least 2 × 2 pixels");
    return height_field_data(std::move(heights), width, height, h.water_level, h.smooth);
  }
  if (kind.colour_type != 0 && kind.colour_type != 2)
    fail_at(h.file_loc, "unsupported: a height_field image with an alpha channel ('" + h.file + "') is a POV-Ray " +
                                     "feature that povtrace does not render yet (grey, RGB and palette PNGs are read)");
  image::Image img;
  try {
    img = jpeg ? image::read_image(h.file) : image::read_png(h.file);
  } catch (const image::ImageError& e) {
    fail_at(h.file_loc, "cannot read the height_field image '" + h.file + "': " + e.what());
  }
  if (img.width < 2 || img.height < 2)
    fail_at(h.file_loc, "the height_field image '" + h.file + "' needs at least 2 × 2 pixels");
  std::vector<std::uint16_t> heights(static_cast<std::size_t>(img.width) * img.height);
  for (int z = 0; z < img.height; ++z)
    for (int x = 0; x < img.width; ++x)
      heights[static_cast<std::size_t>(z) * img.width + x] = height_of(kind, img.pixel(x, img.height - 1 - z));
  return height_field_data(std::move(heights), img.width, img.height, h.water_level, h.smooth);
}
}  // namespace

std::shared_ptr<HeightFieldData> height_field_data(std::vector<std::uint16_t> heights, int width, int depth,
                                                   double water_level, bool smooth) {
  auto d = std::make_shared<HeightFieldData>();
  d->width = width;
  d->depth = depth;
  d->heights = std::move(heights);
  std::uint16_t lo = 65535, hi = 0;
  for (const std::uint16_t v : d->heights) {
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  d->bottom = std::max(static_cast<double>(lo), 65536.0 * water_level) - hfield_offset;
  d->top = hi + hfield_offset;
  d->smooth = smooth;
  if (smooth) smooth_normals(*d);
  return d;
}

Primitive place_height_field(std::shared_ptr<const HeightFieldData> data, const Matrix& world_from_object) {
  Primitive p;
  p.type = ShapeType::height_field;
  p.transformed = true;
  p.world_from_object =
      Matrix::scaling({1.0 / (data->width - 1.0), 1.0 / 65536.0, 1.0 / (data->depth - 1.0)}) * world_from_object;
  p.object_from_world = p.world_from_object.inverse();
  p.data = std::move(data);
  return p;
}

Primitive make_height_field(const HeightField& h, const Matrix& world_from_object) {
  return place_height_field(read_height_field(h), world_from_object);
}

namespace {
// A height field made from a pigment function (`function W, H { pigment { … } }`): POV-Ray's Make_Pattern_Image
// stores the pigment's colour at (j / (W − 1), i / (H − 1), 0) in a 16-bit RGBA image (each channel as
// sdl::function_image_value keeps it), and image_height_at reads a 16-bit colour image as its grey
// 0.297 r + 0.589 g + 0.114 b, · 65535, truncated. The image's bottom row is the height field's z = 0.

// The pigment's patterns use the generator in force when the height field was parsed (POV-Ray samples it then),
// functions in it the scene's (`scene_generator`).
HeightField with_pigment_samples(const HeightField& description, int scene_generator) {
  const HeightField* h = &description;
  if (!h->pigment_function) return description;
  RenderPigment pigment = build_render_pigment(*h->pigment_function);
  set_generator(pigment, static_cast<NoiseGenerator>(h->noise_generator));
  set_function_generator(pigment, scene_generator);
  const int w = h->samples_width, d = h->samples_depth;
  auto samples = std::make_shared<std::vector<std::uint16_t>>(static_cast<std::size_t>(w) * d);
  for (int i = 0; i < d; ++i)
    for (int j = 0; j < w; ++j) {
      const Vec3 p{static_cast<double>(j) / (w - 1), static_cast<double>(i) / (d - 1), 0.0};
      const Colour c = evaluate_pigment(pigment, p);
      const double grey = 0.297 * sdl::function_image_value(c.r) + 0.589 * sdl::function_image_value(c.g) +
                          0.114 * sdl::function_image_value(c.b);
      (*samples)[static_cast<std::size_t>(d - 1 - i) * w + j] = static_cast<std::uint16_t>(grey * 65535.0f);
    }
  HeightField sampled = *h;
  sampled.samples = std::move(samples);
  return sampled;
}
}  // namespace

Primitive shapes::HeightFieldShape::build(const HeightField& description, const Matrix& world_from_object,
                                          const BuildContext& context) {
  return make_height_field(with_pigment_samples(description, context.noise_generator), world_from_object);
}

}  // namespace povtrace::render
