#include "renderer/image/hdr_io.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <ctime>
#include <vector>

#include "renderer/image/dither.hpp"

namespace povtrace::image {
namespace {

using Rgbe = std::array<std::uint8_t, 4>;

constexpr int min_rle_width = 8;       // narrower or wider scanlines are written flat
constexpr int max_rle_width = 0x7fff;
constexpr int min_run = 4;             // shorter repeats go into literal packets
constexpr int max_run = 127;
constexpr std::uint64_t max_pixels = std::uint64_t(1) << 26;

// One pixel as POV-Ray's GetRGBE: shared exponent of the largest component, mantissas truncated; the dither
// error is the value minus the mantissa's bucket centre. A black pixel passes no error on (as in POV-Ray).
Rgbe to_rgbe(const float* p, int x, int y, Ditherer& ditherer) {
  ChannelOffsets linear{}, quantum{};
  ditherer.offsets(x, y, linear, quantum);
  const float c[3] = {p[0] + linear[0], p[1] + linear[1], p[2] + linear[2]};
  float d = std::max({c[0], c[1], c[2]});
  if (!(d > 1.0e-32)) return {0, 0, 0, 0};
  int exponent = 0;
  d = static_cast<float>(std::frexp(d, &exponent) * 256.0 / d);
  Rgbe rgbe{};
  for (std::size_t i = 0; i < 3; ++i) {
    rgbe[i] = static_cast<std::uint8_t>(std::clamp(c[i] * d + quantum[i], 0.0f, 255.0f));
    linear[i] = static_cast<float>(c[i] - (double(rgbe[i]) + 0.5) / d);
  }
  rgbe[3] = static_cast<std::uint8_t>(std::clamp(static_cast<float>(exponent) + 128.0f, 0.0f, 255.0f));
  ditherer.carry(x, linear);
  return rgbe;
}

// One component of a scanline in the new-style RLE, packet for packet as POV-Ray writes it: runs of 4 to 127
// equal bytes as (128 + n, byte), a stretch of 2-3 equal bytes just before a run as a short run, the rest as
// literal packets of up to 128 bytes (n, bytes).
void put_component(std::string& out, const std::vector<Rgbe>& line, std::size_t i) {
  const int width = static_cast<int>(line.size());
  const auto at = [&](int x) { return line[static_cast<std::size_t>(x)][i]; };
  int count = 1;
  for (int col = 0; col < width; col += count) {
    int begin = col;
    for (; begin < width; begin += count) {  // find the next run of at least min_run
      count = 1;
      while (count < max_run && begin + count < width && at(begin + count) == at(begin)) ++count;
      if (count >= min_run) break;
    }
    if (begin - col > 1 && begin - col < min_run) {  // a short run just before it?
      int c2 = col + 1;
      while (at(c2++) == at(col)) {
        if (c2 == begin) {
          out.push_back(static_cast<char>(128 + begin - col));
          out.push_back(static_cast<char>(at(col)));
          col = begin;
          break;
        }
      }
    }
    while (col < begin) {  // literals
      const int n = std::min(begin - col, 128);
      out.push_back(static_cast<char>(n));
      for (int k = 0; k < n; ++k) out.push_back(static_cast<char>(at(col++)));
    }
    if (count >= min_run) {
      out.push_back(static_cast<char>(128 + count));
      out.push_back(static_cast<char>(at(begin)));
    } else {
      count = 0;
    }
  }
}

std::string header(const Image& image) {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char date[64];
  std::strftime(date, sizeof date, "%Y-%m-%d %H:%M:%SZ", &utc);
  return "#?RADIANCE\nSOFTWARE=povtrace\nCREATION_TIME=" + std::string(date) +
         "\nFORMAT=32-bit_rle_rgbe\n\n-Y " + std::to_string(image.height) + " +X " + std::to_string(image.width) +
         "\n";
}

}  // namespace

std::string encode_hdr(const Image& source, const EncodeOptions& options) {
  const Image image = source.encoding == Encoding::linear ? source : to_linear(source);
  Ditherer ditherer(options.dither, image.width);
  std::string out = header(image);
  std::vector<Rgbe> line(static_cast<std::size_t>(image.width));
  const bool rle = image.width >= min_rle_width && image.width <= max_rle_width;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) line[static_cast<std::size_t>(x)] = to_rgbe(image.pixel(x, y), x, y, ditherer);
    if (!rle) {
      for (const Rgbe& p : line) out.append(reinterpret_cast<const char*>(p.data()), 4);
      continue;
    }
    out += {2, 2, static_cast<char>(image.width >> 8), static_cast<char>(image.width & 0xff)};
    for (std::size_t i = 0; i < 4; ++i) put_component(out, line, i);
  }
  return out;
}

namespace {

struct HdrReader {
  const std::string& bytes;
  std::size_t pos = 0;

  std::string line() {
    const std::size_t end = bytes.find('\n', pos);
    if (end == std::string::npos) throw ImageError("bad Radiance header");
    std::string text = bytes.substr(pos, end - pos);
    pos = end + 1;
    return text;
  }
  std::uint8_t byte() {
    if (pos >= bytes.size()) throw ImageError("Radiance pixel data is truncated");
    return static_cast<std::uint8_t>(bytes[pos++]);
  }
};

void read_rle_scanline(HdrReader& in, std::vector<Rgbe>& line) {
  for (std::size_t i = 0; i < 4; ++i) {
    for (std::size_t x = 0; x < line.size();) {
      const std::uint8_t packet = in.byte();
      const std::size_t n = packet > 128 ? packet - 128u : packet;
      if (n == 0 || x + n > line.size()) throw ImageError("bad Radiance run length");
      if (packet > 128) {
        const std::uint8_t value = in.byte();
        for (std::size_t k = 0; k < n; ++k) line[x++][i] = value;
      } else {
        for (std::size_t k = 0; k < n; ++k) line[x++][i] = in.byte();
      }
    }
  }
}

}  // namespace

Image decode_hdr(const std::string& bytes) {
  HdrReader in{bytes};
  const std::string magic = in.line();
  if (magic.rfind("#?", 0) != 0) throw ImageError("not a Radiance file");
  for (std::string text = in.line(); !text.empty(); text = in.line()) {
    if (text.rfind("FORMAT=", 0) == 0 && text != "FORMAT=32-bit_rle_rgbe") {
      throw ImageError("unsupported Radiance format " + text.substr(7));
    }
  }
  int height = 0, width = 0;
  if (std::sscanf(in.line().c_str(), "-Y %d +X %d", &height, &width) != 2 || width <= 0 || height <= 0 ||
      std::uint64_t(width) * std::uint64_t(height) > max_pixels) {
    throw ImageError("unsupported Radiance resolution line (only -Y h +X w)");
  }
  Image image(width, height);
  std::vector<Rgbe> line(static_cast<std::size_t>(width));
  for (int y = 0; y < height; ++y) {
    const bool rle = width >= min_rle_width && width <= max_rle_width && in.pos + 4 <= bytes.size() &&
                     bytes[in.pos] == 2 && bytes[in.pos + 1] == 2 && (static_cast<unsigned char>(bytes[in.pos + 2]) & 0x80) == 0;
    if (rle) {
      in.pos += 4;
      read_rle_scanline(in, line);
    } else {
      for (Rgbe& p : line)
        for (std::uint8_t& b : p) b = in.byte();
    }
    for (int x = 0; x < width; ++x) {
      const Rgbe& p = line[static_cast<std::size_t>(x)];
      const double scale = p[3] == 0 ? 0.0 : std::ldexp(1.0, int(p[3]) - (128 + 8));
      float* out = image.pixel(x, y);
      for (std::size_t c = 0; c < 3; ++c) out[c] = static_cast<float>((double(p[c]) + 0.5) * scale);
    }
  }
  return image;
}

}  // namespace povtrace::image
