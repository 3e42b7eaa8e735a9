#include "renderer/pattern/image_map.hpp"

#include <algorithm>
#include <cmath>

#include "renderer/pattern/pattern_functions.hpp"

namespace povtrace::render {

namespace {
constexpr double kEpsilon = 1e-10;   // POV-Ray's EPSILON, added to every image position (map_pos)
constexpr double kTwoPi = 2.0 * M_PI;

// POV-Ray's wrap(): val modulo limit in [0, limit), fmod's negative results moved up, a rounded-up limit to 0.
double wrap(double value, double limit) {
  double r = std::fmod(value, limit);
  if (r < 0.0) r += limit;
  if (r >= limit) r = 0.0;
  return r;
}


// A mapper's image position before the offsets, in pixels.
struct MappedUv {
  double u, v;
};

std::optional<MappedUv> planar(const ImageMapping& m, Vec3 p) {
  if (m.once && (p.x < 0.0 || p.x > 1.0)) return std::nullopt;
  const double u = std::fmod(p.x * m.width, m.width);
  if (m.once && (p.y < 0.0 || p.y > 1.0)) return std::nullopt;
  return MappedUv{u, std::fmod(p.y * m.height, m.height)};
}

std::optional<MappedUv> spherical(const ImageMapping& m, Vec3 p) {
  const double len = length(p);
  if (len == 0.0) return std::nullopt;
  const Vec3 d = p / len;
  const double phi = 0.5 + std::asin(d.y) / M_PI;
  const double flat = std::sqrt(d.x * d.x + d.z * d.z);
  const double theta = flat == 0.0 ? 0.0 : patterns::angle_around_y(d.x, d.z, flat) / kTwoPi;
  return MappedUv{theta * m.width, phi * m.height};
}

std::optional<MappedUv> cylindrical(const ImageMapping& m, Vec3 p) {
  if (m.once && (p.y < 0.0 || p.y > 1.0)) return std::nullopt;
  const double v = std::fmod(p.y * m.height, m.height);
  const double len = length(p);
  if (len == 0.0) return std::nullopt;
  const double x = p.x / len, z = p.z / len;
  const double flat = std::sqrt(x * x + z * z);
  if (flat == 0.0) return std::nullopt;
  return MappedUv{patterns::angle_around_y(x, z, flat) / kTwoPi * m.width, v};
}

std::optional<MappedUv> torus(const ImageMapping& m, Vec3 p) {
  constexpr double kMajorRadius = 1.0;   // POV-Ray's image gradient x
  const double len = std::sqrt(p.x * p.x + p.z * p.z);
  if (len == 0.0) return std::nullopt;
  const double theta = -patterns::angle_around_y(p.x, p.z, len);
  const double x = len - kMajorRadius;
  const double tube = std::sqrt(x * x + p.y * p.y);
  double phi = std::acos(-x / tube);
  if (p.y > 0.0) phi = kTwoPi - phi;
  return MappedUv{-(theta / kTwoPi) * m.width, phi / kTwoPi * m.height};
}

// One pixel of a map image and its palette index (−1 for other images).
struct IndexedTexel {
  const Texel& colour;
  int index;
};

// no_interpolation: the pixel at an integer-valued position, clamped to the edge with `once`, else wrapped.
IndexedTexel pixel(const MapImage& image, const ImageMapping& m, double x, double y) {
  int ix = 0, iy = 0;
  if (m.once) {
    ix = x < 0.0 ? 0 : x >= m.columns ? m.columns - 1 : static_cast<int>(x);
    iy = y < 0.0 ? 0 : y >= m.rows ? m.rows - 1 : static_cast<int>(y);
  } else {
    ix = static_cast<int>(wrap(x, m.columns));
    iy = static_cast<int>(wrap(y, m.rows));
  }
  return {image.at(ix, iy), image.indexed ? image.index_at(ix, iy) : -1};
}

struct Sum {
  double r = 0, g = 0, b = 0, f = 0, t = 0, index = 0;
  void add(const Texel& c, int i, double w) {
    r += c.r * w;
    g += c.g * w;
    b += c.b * w;
    f += c.f * w;
    t += c.t * w;
    index += i * w;
  }
  void add_pixel(const MapImage& image, const ImageMapping& m, double x, double y, double w) {
    const IndexedTexel p = pixel(image, m, x, y);
    add(p.colour, p.index, w);
  }
  Texel single() const {
    return {static_cast<float>(r), static_cast<float>(g), static_cast<float>(b), static_cast<float>(f),
            static_cast<float>(t)};
  }
};

// Interp: the pixels at (ix, iy), (ix−1, iy), (ix, iy−1), (ix−1, iy−1) around the shifted position.
Sum four_pixels(const MapImage& image, const ImageMapping& m, double x, double y) {
  x += 0.5;
  y += 0.5;
  const int ix = static_cast<int>(x), iy = static_cast<int>(y);
  const double p = x - ix, q = y - iy;
  double w[4];
  if (m.interpolate == 2) {
    w[0] = p * q;
    w[1] = (1 - p) * q;
    w[2] = p * (1 - q);
    w[3] = (1 - p) * (1 - q);
  } else {   // normalised distance
    const double inv[4] = {1.0 / ((1 - p) * (1 - p) + (1 - q) * (1 - q)), 1.0 / (p * p + (1 - q) * (1 - q)),
                           1.0 / ((1 - p) * (1 - p) + q * q), 1.0 / (p * p + q * q)};
    const double total = inv[0] + inv[1] + inv[2] + inv[3];
    for (int i = 0; i < 4; ++i) w[i] = inv[i] / total;
  }
  Sum s;
  s.add_pixel(image, m, ix, iy, w[0]);
  s.add_pixel(image, m, ix - 1.0, iy, w[1]);
  s.add_pixel(image, m, ix, iy - 1.0, w[2]);
  s.add_pixel(image, m, ix - 1.0, iy - 1.0, w[3]);
  return s;
}

void cubic_weights(double x, double w[4]) {
  const double p = x - static_cast<int>(x), q = 1 - p;
  w[0] = -0.5 * p * q * q;
  w[1] = 0.5 * q * (q * (3 * p + 1) + 1);
  w[2] = 0.5 * p * (p * (3 * q + 1) + 1);
  w[3] = -0.5 * q * p * p;
}

Sum sixteen_pixels(const MapImage& image, const ImageMapping& m, double x, double y) {
  x += 0.5;
  y += 0.5;
  const int ix = static_cast<int>(x), iy = static_cast<int>(y);
  double wx[4], wy[4];
  cubic_weights(x, wx);
  cubic_weights(y, wy);
  Sum s;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) s.add_pixel(image, m, ix + i - 2.0, iy + j - 2.0, wx[i] * wy[j]);
  return s;
}
}  // namespace

ImageMapping image_mapping(const ImageMap& map, const MapImage& image) {
  ImageMapping m;
  m.map_type = map.map_type;
  m.interpolate = map.interpolate;
  m.once = map.once;
  m.columns = image.width;
  m.rows = image.height;
  m.width = static_cast<float>(image.width * map.repeat_u);
  m.height = static_cast<float>(image.height * map.repeat_v);
  m.offset_u = map.offset_u * -static_cast<double>(image.width);
  m.offset_v = map.offset_v * -static_cast<double>(image.height);
  return m;
}

std::optional<std::array<double, 2>> image_position(const ImageMapping& m, Vec3 p) {
  std::optional<MappedUv> mapped;
  switch (m.map_type) {
    case 1: mapped = spherical(m, p); break;
    case 2: mapped = cylindrical(m, p); break;
    case 5: mapped = torus(m, p); break;
    default: mapped = planar(m, p); break;
  }
  if (!mapped) return std::nullopt;
  const double u = mapped->u + (m.offset_u + kEpsilon);
  const double v = mapped->v + (m.offset_v + kEpsilon);
  if (m.once && (u >= m.columns || v >= m.rows || u < 0.0 || v < 0.0)) return std::nullopt;
  // Rows count from the image's top, v upwards: v is negated.
  return std::array<double, 2>{wrap(u, m.columns), wrap(-v, m.rows)};
}

ImageSample image_sample_at(const MapImage& image, const ImageMapping& m, double column, double row) {
  Sum s;
  switch (m.interpolate) {
    case 2:
    case 4: s = four_pixels(image, m, column, row); break;
    case 3: s = sixteen_pixels(image, m, column, row); break;
    default: {
      const IndexedTexel t = pixel(image, m, column, row);
      return {t.colour, t.index};
    }
  }
  return {s.single(), static_cast<int>(s.index)};
}

std::optional<Colour> image_map_colour(const MapImage& image, const ImageMapping& m, Vec3 p) {
  const auto at = image_position(m, p);
  if (!at) return std::nullopt;
  const Texel c = image_colour_at(image, m, (*at)[0], (*at)[1]);
  return Colour{c.r, c.g, c.b, c.f, c.t};
}

std::size_t material_map_index(const RenderImageMap& image, Vec3 pattern_point, std::size_t count) {
  const std::optional<std::array<double, 2>> at = image_position(image.mapping, pattern_point);
  long number = 0;
  if (at) {
    const ImageSample s = image_sample_at(*image.image, image.mapping, (*at)[0], (*at)[1]);
    number = s.index == -1 ? static_cast<long>(s.colour.r * 255.0) : s.index;
  }
  const long n = static_cast<long>(count);
  if (number > n) number %= n;
  return static_cast<std::size_t>(std::clamp(number, 0L, n - 1));
}

double image_pattern_value(const RenderImageMap& image, Vec3 pattern_point) {
  const std::optional<std::array<double, 2>> at = image_position(image.mapping, pattern_point);
  if (!at) return 0.0;
  const Texel c = image_colour_at(*image.image, image.mapping, (*at)[0], (*at)[1]);
  double value;
  if (image.use_alpha) value = image.image->alpha_channel ? c.t : c.r;
  else value = static_cast<float>(0.297 * c.r + 0.589 * c.g + 0.114 * c.b);
  return std::clamp(value, 0.0, 1.0);
}

}  // namespace povtrace::render

namespace povtrace::render::patterns {

double angle_around_y(double x, double z, double len) {
  if (z == 0.0) return x > 0 ? 0.0 : M_PI;
  const double theta = std::acos(x / len);
  return z < 0.0 ? 2.0 * M_PI - theta : theta;
}

}  // namespace povtrace::render::patterns
