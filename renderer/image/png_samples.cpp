#include "renderer/image/png_samples.hpp"

#include <csetjmp>
#include <vector>

#include "renderer/image/png_common.hpp"

namespace povtrace::image {

namespace {
using namespace png_detail;

constexpr std::uint64_t max_pixels = std::uint64_t(1) << 26;

// Header and chunks; asks libpng for one byte per sub-byte sample (values unscaled) and de-interlaced rows.
bool run_read_header(PngReader& r, std::FILE* f, PngSamples& out) {
  if (setjmp(png_jmpbuf(r.png))) return false;
  png_init_io(r.png, f);
  png_read_info(r.png, r.info);
  out.width = static_cast<int>(png_get_image_width(r.png, r.info));
  out.height = static_cast<int>(png_get_image_height(r.png, r.info));
  out.bit_depth = png_get_bit_depth(r.png, r.info);
  out.colour_type = png_get_color_type(r.png, r.info);
  out.channels = png_get_channels(r.png, r.info);
  out.srgb_chunk = png_get_valid(r.png, r.info, PNG_INFO_sRGB) != 0;
  double gamma = 0;
  if (png_get_valid(r.png, r.info, PNG_INFO_gAMA) != 0 && png_get_gAMA(r.png, r.info, &gamma) != 0)
    out.file_gamma = gamma;
  if (out.colour_type == PNG_COLOR_TYPE_PALETTE) {
    png_colorp palette = nullptr;
    int count = 0;
    if (png_get_PLTE(r.png, r.info, &palette, &count) != 0)
      for (int i = 0; i < count; ++i) out.palette.push_back({palette[i].red, palette[i].green, palette[i].blue});
  }
  out.has_trns = png_get_valid(r.png, r.info, PNG_INFO_tRNS) != 0;
  if (out.has_trns && out.colour_type == PNG_COLOR_TYPE_PALETTE) {
    png_bytep alpha = nullptr;
    int count = 0;
    png_get_tRNS(r.png, r.info, &alpha, &count, nullptr);
    if (alpha != nullptr) out.palette_alpha.assign(alpha, alpha + count);
  }
  if (out.bit_depth < 8) png_set_packing(r.png);
  png_set_interlace_handling(r.png);
  png_read_update_info(r.png, r.info);
  return true;
}

bool run_read_rows(PngReader& r, png_bytepp rows) {
  if (setjmp(png_jmpbuf(r.png))) return false;
  png_read_image(r.png, rows);
  png_read_end(r.png, nullptr);
  return true;
}
}  // namespace

PngSamples read_png_samples(const std::filesystem::path& file) {
  FilePtr f = open_file(file, "rb");
  PngReader reader;
  PngSamples out;
  if (!run_read_header(reader, f.get(), out)) throw ImageError(std::string("libpng: ") + reader.error.text);
  if (out.width <= 0 || out.height <= 0 || std::uint64_t(out.width) * std::uint64_t(out.height) > max_pixels)
    throw ImageError("PNG too large");
  const std::size_t row_bytes = png_get_rowbytes(reader.png, reader.info);
  const auto height = static_cast<std::size_t>(out.height);
  std::vector<png_byte> bytes(row_bytes * height);
  std::vector<png_bytep> rows(height);
  for (std::size_t y = 0; y < height; ++y) rows[y] = bytes.data() + y * row_bytes;
  if (!run_read_rows(reader, rows.data())) throw ImageError(std::string("libpng: ") + reader.error.text);
  const std::size_t count = static_cast<std::size_t>(out.width) * height * static_cast<std::size_t>(out.channels);
  out.samples.resize(count);
  const bool wide = out.bit_depth == 16;
  for (std::size_t y = 0; y < height; ++y)
    for (std::size_t i = 0; i < count / height; ++i) {
      const png_byte* p = rows[y] + i * (wide ? 2 : 1);
      out.samples[y * (count / height) + i] = wide ? static_cast<std::uint16_t>((p[0] << 8) | p[1]) : p[0];
    }
  return out;
}

}  // namespace povtrace::image
