#include "renderer/image/tga_io.hpp"

#include <array>
#include <cstdint>
#include <cstring>
#include <ctime>

#include "renderer/image/display_encode.hpp"
#include "renderer/image/encoded_file.hpp"

namespace povtrace::image {
namespace {

constexpr std::size_t header_size = 18;
constexpr std::size_t extension_size = 495;   // TGA 2.0 extension area
constexpr unsigned char type_true_colour = 2;
constexpr unsigned char type_true_colour_rle = 10;
constexpr unsigned char type_grey = 3;
constexpr unsigned char type_grey_rle = 11;
constexpr unsigned char descriptor_top_left = 0x20;
constexpr std::size_t max_run = 128;          // pixels per RLE packet

using Pixel = std::array<std::uint8_t, 4>;  // B, G, R, A

std::string header(const Image& image, bool alpha, bool run_length) {
  std::string out(header_size, '\0');
  out[2] = static_cast<char>(run_length ? type_true_colour_rle : type_true_colour);
  out.resize(12);
  put_le16(out, static_cast<unsigned>(image.width));
  put_le16(out, static_cast<unsigned>(image.height));
  out.push_back(static_cast<char>(alpha ? 32 : 24));
  out.push_back(static_cast<char>(alpha ? descriptor_top_left | 8 : descriptor_top_left));  // 8 alpha bits
  return out;
}

void put_pixel(std::string& out, const Pixel& p, bool alpha) {
  out.append(reinterpret_cast<const char*>(p.data()), alpha ? 4 : 3);
}

// One row as POV-Ray packs it: a run packet (0x80 | count − 1, one pixel) for repeats, a raw packet (count − 1,
// the pixels) for the rest, at most 128 pixels each; a raw stretch ends one pixel early where a repeat begins.
// One difference: after a raw packet of the full 128 pixels POV-Ray compares the next pixels with the packet's
// last pixel instead of the next packet's first, and may then write a run of that stale pixel (a wrong image);
// here every packet starts from its own first pixel.
void put_rle_row(std::string& out, const Pixel* row, std::size_t width, bool alpha) {
  std::size_t start = 0;
  while (start < width) {
    std::size_t count = 1;
    bool raw = false;
    Pixel current = row[start];
    while (true) {
      const Pixel next = start + count < width ? row[start + count] : current;
      if (next == current && !raw) {
        if (++count >= max_run || start + count >= width) break;
      } else if (next == current) {
        --count;  // the last raw pixel starts the next run
        break;
      } else if (raw || count <= 1) {
        current = next;
        raw = true;
        if (++count >= max_run || start + count >= width) break;
      } else {
        break;
      }
    }
    if (start + count > width) count = width - start;
    out.push_back(static_cast<char>(raw ? count - 1 : (count - 1) | 0x80));
    for (std::size_t i = 0; i < (raw ? count : 1); ++i) put_pixel(out, row[start + i], alpha);
    start += count;
  }
}

// The extension area fields POV-Ray fills: size, software, date, version, gamma, scan-line offset, alpha type.
std::string extension_area(bool alpha, float decoding_gamma) {
  std::string ext(extension_size, '\0');
  ext[0] = static_cast<char>(extension_size & 0xff);
  ext[1] = static_cast<char>(extension_size >> 8);
  std::memcpy(&ext[426], "povtrace", 8);  // software ID (41 bytes)
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  std::string date;
  for (const int v : {utc.tm_mon + 1, utc.tm_mday, utc.tm_year + 1900, utc.tm_hour, utc.tm_min, utc.tm_sec}) {
    put_le16(date, static_cast<unsigned>(v));
  }
  ext.replace(367, 12, date);
  ext[469] = ' ';  // software version letter: POV-Ray writes 0, 0, ' '
  // Gamma as a fraction over 6553, as POV-Ray writes it (so that 10.0 still fits in 16 bits).
  std::string gamma;
  put_le16(gamma, static_cast<unsigned>(static_cast<int>(6553.0 * decoding_gamma)));
  put_le16(gamma, 6553);
  ext.replace(478, 4, gamma);
  ext[490] = static_cast<char>(header_size);  // scan-line table offset: POV-Ray writes 18
  ext[494] = static_cast<char>(alpha ? 3 : 0);  // 3: straight alpha
  return ext;
}

std::string footer(std::size_t extension_offset) {
  std::string out;
  put_le32(out, static_cast<std::uint32_t>(extension_offset));
  put_le32(out, 0);  // no developer area
  out += "TRUEVISION-XFILE.";
  out.push_back('\0');
  return out;
}

}  // namespace

std::string encode_tga(const Image& image, const EncodeOptions& options, bool run_length) {
  if (image.width > 0xffff || image.height > 0xffff) throw ImageError("Targa images are at most 65535 pixels wide");
  SampleLayout layout;
  layout.alpha = image.has_alpha;
  layout.curve = TransferCurve::from_file_gamma(options.file_gamma);
  layout.dither = options.dither;
  // POV-Ray encodes every Targa pixel through its RGBA path; without alpha (α = 1) that is the RGB path.
  const std::vector<std::uint16_t> samples = encode_samples(image, layout);
  const std::size_t channels = layout.alpha ? 4 : 3;
  const auto width = static_cast<std::size_t>(image.width);
  std::vector<Pixel> pixels(samples.size() / channels);
  for (std::size_t i = 0; i < pixels.size(); ++i) {
    const std::uint16_t* s = &samples[i * channels];
    pixels[i] = {static_cast<std::uint8_t>(s[2]), static_cast<std::uint8_t>(s[1]), static_cast<std::uint8_t>(s[0]),
                 static_cast<std::uint8_t>(layout.alpha ? s[3] : 255)};
  }
  std::string out = header(image, layout.alpha, run_length);
  for (std::size_t y = 0; y < static_cast<std::size_t>(image.height); ++y) {
    const Pixel* row = &pixels[y * width];
    if (run_length) {
      put_rle_row(out, row, width, layout.alpha);
    } else {
      for (std::size_t x = 0; x < width; ++x) put_pixel(out, row[x], layout.alpha);
    }
  }
  const std::size_t extension_offset = out.size();
  out += extension_area(layout.alpha, layout.curve.approximate_decoding_gamma());
  out += footer(extension_offset);
  return out;
}

namespace {

struct TgaReader {
  const std::string& bytes;
  std::size_t pos;
  std::size_t pixel_bytes;

  Pixel pixel() {
    if (pos + pixel_bytes > bytes.size()) throw ImageError("Targa pixel data is truncated");
    Pixel p{0, 0, 0, 255};
    const auto* b = reinterpret_cast<const unsigned char*>(bytes.data() + pos);
    if (pixel_bytes == 1) {
      p = {b[0], b[0], b[0], 255};
    } else {
      p = {b[0], b[1], b[2], static_cast<std::uint8_t>(pixel_bytes == 4 ? b[3] : 255)};
    }
    pos += pixel_bytes;
    return p;
  }

  unsigned char byte() {
    if (pos >= bytes.size()) throw ImageError("Targa pixel data is truncated");
    return static_cast<unsigned char>(bytes[pos++]);
  }
};

}  // namespace

Image decode_tga(const std::string& bytes) {
  if (bytes.size() < header_size) throw ImageError("not a Targa file (too short)");
  const auto type = static_cast<unsigned char>(bytes[2]);
  const bool rle = type == type_true_colour_rle || type == type_grey_rle;
  const bool grey = type == type_grey || type == type_grey_rle;
  const unsigned depth = static_cast<unsigned char>(bytes[16]);
  const unsigned descriptor = static_cast<unsigned char>(bytes[17]);
  if (type != type_true_colour && !rle && type != type_grey) throw ImageError("unsupported Targa image type");
  if (grey ? depth != 8 : depth != 24 && depth != 32) throw ImageError("unsupported Targa pixel depth");
  if (bytes[1] != 0) throw ImageError("Targa colour-mapped images are not supported");
  const int width = static_cast<int>(get_le16(bytes, 12));
  const int height = static_cast<int>(get_le16(bytes, 14));
  if (width == 0 || height == 0) throw ImageError("bad Targa size");
  Image image(width, height);
  image.encoding = Encoding::encoded;
  image.has_alpha = depth == 32;
  TgaReader reader{bytes, header_size + static_cast<unsigned char>(bytes[0]), depth / 8};
  const std::size_t count = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  std::vector<Pixel> pixels;
  pixels.reserve(count);
  while (pixels.size() < count) {
    if (!rle) {
      pixels.push_back(reader.pixel());
      continue;
    }
    const unsigned char packet = reader.byte();
    const std::size_t n = (packet & 0x7fu) + 1u;
    if (packet & 0x80u) {
      const Pixel p = reader.pixel();
      for (std::size_t i = 0; i < n && pixels.size() < count; ++i) pixels.push_back(p);
    } else {
      for (std::size_t i = 0; i < n && pixels.size() < count; ++i) pixels.push_back(reader.pixel());
    }
  }
  const bool top_first = (descriptor & descriptor_top_left) != 0;
  const bool right_first = (descriptor & 0x10u) != 0;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const Pixel& p = pixels[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                              static_cast<std::size_t>(x)];
      float* out = image.pixel(right_first ? width - 1 - x : x, top_first ? y : height - 1 - y);
      const float alpha = image.has_alpha ? p[3] / 255.0f : 1.0f;
      out[0] = p[2] / 255.0f * alpha;
      out[1] = p[1] / 255.0f * alpha;
      out[2] = p[0] / 255.0f * alpha;
      out[3] = alpha;
    }
  }
  return image;
}

}  // namespace povtrace::image
