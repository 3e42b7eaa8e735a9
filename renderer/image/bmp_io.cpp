#include "renderer/image/bmp_io.hpp"

#include <cstdint>
#include <cstdlib>
#include <vector>

#include "renderer/image/display_encode.hpp"
#include "renderer/image/encoded_file.hpp"

namespace povtrace::image {
namespace {

constexpr std::uint32_t file_header_size = 14;
constexpr std::uint32_t info_header_size = 40;  // BITMAPINFOHEADER
constexpr std::uint32_t bi_rgb = 0;             // no compression
constexpr std::uint64_t max_pixels = std::uint64_t(1) << 26;

std::size_t row_bytes(std::size_t width, unsigned bits_per_pixel) { return (width * bits_per_pixel + 31) / 32 * 4; }

}  // namespace

std::string encode_bmp(const Image& image, const EncodeOptions& options) {
  SampleLayout layout;
  layout.alpha = image.has_alpha;
  layout.curve = TransferCurve::from_file_gamma(options.file_gamma);
  layout.dither = options.dither;
  layout.bottom_up = true;  // POV-Ray visits (and dithers) the rows in file order
  const std::vector<std::uint16_t> samples = encode_samples(image, layout);
  const unsigned bits = layout.alpha ? 32 : 24;
  const auto width = static_cast<std::size_t>(image.width);
  const std::size_t stride = row_bytes(width, bits);
  const auto data_size = static_cast<std::uint32_t>(stride * static_cast<std::size_t>(image.height));
  std::string out = "BM";
  put_le32(out, file_header_size + info_header_size + data_size);
  put_le32(out, 0);  // two reserved shorts
  put_le32(out, file_header_size + info_header_size);
  put_le32(out, info_header_size);
  put_le32(out, static_cast<std::uint32_t>(image.width));
  put_le32(out, static_cast<std::uint32_t>(image.height));
  put_le16(out, 1);  // planes
  put_le16(out, bits);
  put_le32(out, bi_rgb);
  put_le32(out, data_size);
  for (int i = 0; i < 4; ++i) put_le32(out, 0);  // resolution x, y; colours used, important
  const std::size_t channels = layout.alpha ? 4 : 3;
  for (std::size_t row = 0; row < static_cast<std::size_t>(image.height); ++row) {
    const std::size_t row_start = out.size();
    for (std::size_t x = 0; x < width; ++x) {
      const std::uint16_t* s = &samples[(row * width + x) * channels];
      for (const std::size_t c : {std::size_t(2), std::size_t(1), std::size_t(0)}) out.push_back(static_cast<char>(s[c]));
      if (layout.alpha) out.push_back(static_cast<char>(s[3]));
    }
    out.resize(row_start + stride, '\0');
  }
  return out;
}

Image decode_bmp(const std::string& bytes) {
  if (bytes.size() < file_header_size + info_header_size || bytes[0] != 'B' || bytes[1] != 'M') {
    throw ImageError("not a BMP file");
  }
  const std::uint32_t data_offset = get_le32(bytes, 10);
  const std::uint32_t header_size = get_le32(bytes, 14);
  if (header_size < info_header_size) throw ImageError("unsupported BMP header (OS/2)");
  const auto width = static_cast<std::int32_t>(get_le32(bytes, 18));
  const auto signed_height = static_cast<std::int32_t>(get_le32(bytes, 22));
  const unsigned bits = get_le16(bytes, 28);
  const std::uint32_t compression = get_le32(bytes, 30);
  if (compression != bi_rgb || (bits != 24 && bits != 32)) throw ImageError("only uncompressed 24- and 32-bit BMP");
  const bool top_first = signed_height < 0;
  const std::int64_t height = std::llabs(static_cast<long long>(signed_height));
  if (width <= 0 || height == 0 || std::uint64_t(width) * std::uint64_t(height) > max_pixels) {
    throw ImageError("bad BMP size");
  }
  const std::size_t stride = row_bytes(static_cast<std::size_t>(width), bits);
  if (data_offset > bytes.size() || bytes.size() - data_offset < stride * static_cast<std::size_t>(height)) {
    throw ImageError("BMP pixel data is truncated");
  }
  Image image(width, static_cast<int>(height));
  image.encoding = Encoding::encoded;
  const std::size_t pixel_bytes = bits / 8;
  const auto* data = reinterpret_cast<const unsigned char*>(bytes.data() + data_offset);
  const auto at = [&](std::int64_t row, std::int32_t x) { return data + static_cast<std::size_t>(row) * stride + static_cast<std::size_t>(x) * pixel_bytes; };
  if (bits == 32) {
    for (std::int64_t row = 0; row < height && !image.has_alpha; ++row)
      for (std::int32_t x = 0; x < width && !image.has_alpha; ++x) image.has_alpha = at(row, x)[3] != 0;
  }
  for (std::int64_t row = 0; row < height; ++row) {
    for (std::int32_t x = 0; x < width; ++x) {
      const unsigned char* p = at(row, x);
      const float alpha = image.has_alpha ? p[3] / 255.0f : 1.0f;
      float* out = image.pixel(x, static_cast<int>(top_first ? row : height - 1 - row));
      out[0] = p[2] / 255.0f * alpha;
      out[1] = p[1] / 255.0f * alpha;
      out[2] = p[0] / 255.0f * alpha;
      out[3] = alpha;
    }
  }
  return image;
}

}  // namespace povtrace::image
