#include "renderer/image/ppm_io.hpp"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "renderer/image/display_encode.hpp"
#include "renderer/image/encoded_file.hpp"

namespace povtrace::image {
namespace {

namespace fs = std::filesystem;

constexpr std::uint64_t max_pixels = std::uint64_t(1) << 26;  // 1 GiB of floats: refuse larger files

std::string header_text(const Image& image, const char* magic, unsigned max_value) {
  return std::string(magic) + "\n" + std::to_string(image.width) + " " + std::to_string(image.height) + "\n" +
         std::to_string(max_value) + "\n";
}

std::string sample_bytes(const std::vector<std::uint16_t>& samples, bool wide) {
  std::string bytes;
  bytes.reserve(samples.size() * (wide ? 2 : 1));
  for (const std::uint16_t s : samples) {
    if (wide) bytes.push_back(static_cast<char>(s >> 8));
    bytes.push_back(static_cast<char>(s & 0xff));
  }
  return bytes;
}

// A cursor over the whole file's bytes for the header's whitespace-separated numbers.
struct HeaderReader {
  const std::string& bytes;
  std::size_t pos = 0;

  void skip_space_and_comments() {
    while (pos < bytes.size()) {
      if (bytes[pos] == '#') {
        while (pos < bytes.size() && bytes[pos] != '\n') ++pos;
      } else if (std::isspace(static_cast<unsigned char>(bytes[pos]))) {
        ++pos;
      } else {
        return;
      }
    }
  }

  unsigned long number(const char* what) {
    skip_space_and_comments();
    unsigned long value = 0;
    const std::size_t start = pos;
    while (pos < bytes.size() && std::isdigit(static_cast<unsigned char>(bytes[pos])) && pos - start < 9) {
      value = value * 10 + static_cast<unsigned long>(bytes[pos++] - '0');
    }
    if (pos == start) throw ImageError(std::string("bad PPM header: expected the ") + what);
    return value;
  }
};

Image image_from_samples(const std::string& bytes, std::size_t pos, int width, int height, unsigned long max_value,
                         std::size_t channels) {
  Image image(width, height);
  image.encoding = Encoding::encoded;
  const bool wide = max_value > 255;
  const std::size_t count = image.rgba.size() / 4 * channels;
  if (bytes.size() - pos < count * (wide ? 2 : 1)) throw ImageError("PPM pixel data is truncated");
  const auto* data = reinterpret_cast<const unsigned char*>(bytes.data() + pos);
  for (std::size_t i = 0; i < count; ++i) {
    const unsigned value = wide ? (unsigned(data[2 * i]) << 8) | data[2 * i + 1] : data[i];
    const auto v = static_cast<float>(double(value) / double(max_value));
    if (channels == 3) {
      image.rgba[i / 3 * 4 + i % 3] = v;
    } else {
      std::fill_n(&image.rgba[i * 4], 3, v);
    }
  }
  return image;
}

}  // namespace

std::string encode_ppm(const Image& image, const EncodeOptions& options) {
  const int bits = options.bits_per_channel;
  SampleLayout layout;
  layout.max_value = (1u << bits) - 1u;
  layout.grey = options.grayscale;
  // POV-Ray's greyscale PGM ignores File_Gamma and stores linear values ("to mimic old code", ppm.cpp).
  layout.curve = options.grayscale ? TransferCurve{TransferCurve::Kind::neutral, 1.0f}
                                   : TransferCurve::from_file_gamma(options.file_gamma);
  layout.dither = options.dither;
  // Samples are stored unscaled (maxval 2^bits − 1), in one byte up to 8 bits and two (big-endian) above.
  // POV-Ray writes two bytes for every PGM sample even when maxval is 255, which no reader accepts; here a PGM
  // of 8 bits or fewer has one byte per sample like any other PNM.
  return header_text(image, options.grayscale ? "P5" : "P6", layout.max_value) +
         sample_bytes(encode_samples(image, layout), bits > 8);
}

void write_ppm(const Image& image, const fs::path& file, int bits_per_channel) {
  EncodeOptions options;
  options.bits_per_channel = bits_per_channel;
  write_bytes(file, encode_ppm(image, options));
}

Image read_ppm(const fs::path& file) {
  const std::string bytes = read_bytes(file);
  if (bytes.size() < 2 || bytes[0] != 'P' || (bytes[1] != '6' && bytes[1] != '5')) {
    throw ImageError("not a binary PPM (P6) or PGM (P5) file");
  }
  HeaderReader header{bytes, 2};
  const unsigned long width = header.number("width");
  const unsigned long height = header.number("height");
  const unsigned long max_value = header.number("maximum value");
  if (width == 0 || height == 0 || std::uint64_t(width) * height > max_pixels) throw ImageError("bad PPM size");
  if (max_value == 0 || max_value > 65535) throw ImageError("bad PPM maximum value");
  if (header.pos >= bytes.size() || !std::isspace(static_cast<unsigned char>(bytes[header.pos]))) {
    throw ImageError("bad PPM header: no whitespace before the pixel data");
  }
  return image_from_samples(bytes, header.pos + 1, static_cast<int>(width), static_cast<int>(height), max_value,
                            bytes[1] == '6' ? 3 : 1);
}

}  // namespace povtrace::image
