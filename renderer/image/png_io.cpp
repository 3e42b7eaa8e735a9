// libpng reports errors by longjmp. Every libpng call that can fail runs inside a small function that calls
// setjmp and owns no C++ objects, so a longjmp never skips a destructor; C++ buffers are allocated outside.
#include "renderer/image/png_io.hpp"

#include <png.h>

#include <cerrno>
#include <csetjmp>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "renderer/image/display_encode.hpp"
#include "renderer/image/encoded_file.hpp"
#include "renderer/image/png_common.hpp"

namespace povtrace::image {
namespace {

using namespace png_detail;

namespace fs = std::filesystem;

constexpr std::uint64_t max_pixels = std::uint64_t(1) << 26;  // 1 GiB of floats: refuse larger files

// ---- writing -------------------------------------------------------------------------------------------------

struct PngWriter {
  PngErrorText error;
  png_structp png = nullptr;
  png_infop info = nullptr;

  PngWriter() {
    png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &error, on_png_error, on_png_warning);
    if (png != nullptr) info = png_create_info_struct(png);
    if (info == nullptr) {
      png_destroy_write_struct(&png, nullptr);
      throw ImageError("libpng: out of memory");
    }
  }
  ~PngWriter() { png_destroy_write_struct(&png, &info); }
  PngWriter(const PngWriter&) = delete;
  PngWriter& operator=(const PngWriter&) = delete;
};

struct PngLayout {
  png_uint_32 width, height;
  int bit_depth, color_type;
};

// The chunks POV-Ray 3.7 writes before the pixels (png.cpp), other than its tIME and tEXt metadata.
struct PngChunks {
  png_color_8 significant_bits{};  // sBIT: the requested Bits_Per_Color
  double file_gamma = 0;           // gAMA: 1 / the curve's approximate decoding gamma
  bool srgb = false;               // sRGB: only for the sRGB curve
};

void append_png_data(png_structp png, png_bytep data, png_size_t length) {
  auto* out = static_cast<std::string*>(png_get_io_ptr(png));
  try {
    out->append(reinterpret_cast<const char*>(data), length);
  } catch (const std::bad_alloc&) {
    png_error(png, "out of memory");
  }
}

void flush_png_data(png_structp) {}

// `text`: a tEXt chunk's key and value, or null for none.
bool run_png_write(PngWriter& w, std::string* out, const PngLayout& layout, PngChunks& chunks, png_bytepp rows,
                   png_text* text) {
  if (setjmp(png_jmpbuf(w.png))) return false;
  png_set_write_fn(w.png, out, append_png_data, flush_png_data);
  png_set_IHDR(w.png, w.info, layout.width, layout.height, layout.bit_depth, layout.color_type,
               PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_set_sBIT(w.png, w.info, &chunks.significant_bits);
  png_set_gAMA(w.png, w.info, chunks.file_gamma);
  if (chunks.srgb) png_set_sRGB(w.png, w.info, PNG_sRGB_INTENT_PERCEPTUAL);
  png_set_oFFs(w.png, w.info, 0, 0, PNG_OFFSET_PIXEL);
  if (text != nullptr) png_set_text(w.png, w.info, text, 1);
  png_write_info(w.png, w.info);
  png_write_image(w.png, rows);
  png_write_end(w.png, nullptr);
  return true;
}

// A `bits`-bit sample widened to the 8- or 16-bit container by left bit replication, as POV-Ray stores
// Bits_Per_Color 5-7 and 9-15 (the sBIT chunk records the true depth).
unsigned widen(unsigned sample, int bits) {
  const int container = bits <= 8 ? 8 : 16;
  if (bits == container) return sample;
  return ((sample << (container - bits)) | (sample >> (2 * bits - container))) & ((1u << container) - 1u);
}

// Samples as PNG bytes: one byte each in an 8-bit container, big-endian pairs in a 16-bit one.
std::vector<png_byte> to_png_bytes(const std::vector<std::uint16_t>& samples, int bits) {
  std::vector<png_byte> bytes;
  bytes.reserve(samples.size() * (bits > 8 ? 2 : 1));
  for (const std::uint16_t s : samples) {
    const unsigned wide = widen(s, bits);
    if (bits > 8) bytes.push_back(static_cast<png_byte>(wide >> 8));
    bytes.push_back(static_cast<png_byte>(wide & 0xff));
  }
  return bytes;
}

std::vector<png_bytep> row_pointers(std::vector<png_byte>& bytes, std::size_t height) {
  std::vector<png_bytep> rows(height);
  const std::size_t stride = height == 0 ? 0 : bytes.size() / height;
  for (std::size_t y = 0; y < height; ++y) rows[y] = bytes.data() + y * stride;
  return rows;
}

PngChunks chunks_for(const SampleLayout& layout, int bits) {
  PngChunks chunks;
  const auto b = static_cast<png_byte>(bits);
  if (layout.grey) {
    chunks.significant_bits.gray = b;
  } else {
    chunks.significant_bits.red = chunks.significant_bits.green = chunks.significant_bits.blue = b;
  }
  if (layout.alpha) chunks.significant_bits.alpha = b;
  chunks.file_gamma = 1.0f / layout.curve.approximate_decoding_gamma();
  chunks.srgb = layout.curve.kind == TransferCurve::Kind::srgb;
  return chunks;
}

// ---- reading -------------------------------------------------------------------------------------------------

// Reads the header and asks libpng for 8- or 16-bit RGB(A) rows whatever the file's layout.
// `region`: the povtrace:region text chunk's value (at most its size − 1 characters), empty when absent.
bool run_png_read_header(PngReader& r, std::FILE* f, PngLayout& layout, int& channels, char (&region)[128]) {
  if (setjmp(png_jmpbuf(r.png))) return false;
  png_init_io(r.png, f);
  png_read_info(r.png, r.info);
  png_textp texts = nullptr;
  const int count = png_get_text(r.png, r.info, &texts, nullptr);
  for (int i = 0; i < count; ++i) {
    if (std::strcmp(texts[i].key, region_key) == 0) std::snprintf(region, sizeof region, "%s", texts[i].text);
  }
  png_set_expand(r.png);  // palette → RGB, grey < 8 bits → 8 bits, tRNS → alpha
  png_set_gray_to_rgb(r.png);
  png_set_interlace_handling(r.png);
  png_read_update_info(r.png, r.info);
  layout = {png_get_image_width(r.png, r.info), png_get_image_height(r.png, r.info),
            png_get_bit_depth(r.png, r.info), png_get_color_type(r.png, r.info)};
  channels = png_get_channels(r.png, r.info);
  return true;
}

bool run_png_read_rows(PngReader& r, png_bytepp rows) {
  if (setjmp(png_jmpbuf(r.png))) return false;
  png_read_image(r.png, rows);
  png_read_end(r.png, nullptr);
  return true;
}

double sample_at(const png_byte* p, int bits) {
  return bits == 16 ? double((p[0] << 8) | p[1]) / 65535.0 : double(p[0]) / 255.0;
}

Image image_from_rows(const std::vector<png_byte>& bytes, const PngLayout& layout, int channels) {
  Image image(static_cast<int>(layout.width), static_cast<int>(layout.height));
  image.encoding = Encoding::encoded;
  image.has_alpha = channels == 4;
  const std::size_t sample_bytes = layout.bit_depth == 16 ? 2 : 1;
  for (std::size_t i = 0; i < image.rgba.size() / 4; ++i) {
    const png_byte* p = &bytes[i * channels * sample_bytes];
    const double alpha = image.has_alpha ? sample_at(p + 3 * sample_bytes, layout.bit_depth) : 1.0;
    for (std::size_t c = 0; c < 3; ++c) {
      image.rgba[i * 4 + c] = static_cast<float>(sample_at(p + c * sample_bytes, layout.bit_depth) * alpha);
    }
    image.rgba[i * 4 + 3] = static_cast<float>(alpha);
  }
  return image;
}

void check_layout(const PngLayout& layout, int channels) {
  const bool supported = (channels == 3 || channels == 4) && (layout.bit_depth == 8 || layout.bit_depth == 16);
  if (!supported) throw ImageError("unsupported PNG layout after expansion");
  if (std::uint64_t(layout.width) * layout.height > max_pixels) throw ImageError("PNG too large");
}

}  // namespace

std::string encode_png(const Image& image, const EncodeOptions& options) {
  // POV-Ray writes greyscale PNGs with 16 bits whatever Bits_Per_Color says.
  const int bits = options.grayscale ? 16 : options.bits_per_channel;
  SampleLayout layout;
  layout.max_value = (1u << bits) - 1u;
  layout.alpha = image.has_alpha;
  layout.grey = options.grayscale;
  layout.curve = TransferCurve::from_file_gamma(options.file_gamma);
  layout.dither = options.dither;
  std::vector<png_byte> bytes = to_png_bytes(encode_samples(image, layout), bits);
  std::vector<png_bytep> rows = row_pointers(bytes, static_cast<std::size_t>(image.height));
  const int colour = layout.grey ? PNG_COLOR_TYPE_GRAY : PNG_COLOR_TYPE_RGB;
  const PngLayout png_layout{static_cast<png_uint_32>(image.width), static_cast<png_uint_32>(image.height),
                             bits > 8 ? 16 : 8, colour | (layout.alpha ? PNG_COLOR_MASK_ALPHA : 0)};
  PngChunks chunks = chunks_for(layout, bits);
  std::string key = region_key, value = image.region ? region_text(*image.region, image.width, image.height) : "";
  png_text text{};
  text.compression = PNG_TEXT_COMPRESSION_NONE;
  text.key = key.data();
  text.text = value.data();
  text.text_length = value.size();
  std::string out;
  PngWriter writer;
  if (!run_png_write(writer, &out, png_layout, chunks, rows.data(), image.region ? &text : nullptr)) {
    throw ImageError(std::string("libpng: ") + writer.error.text);
  }
  return out;
}

void write_png(const Image& image, const fs::path& file, int bits_per_channel) {
  EncodeOptions options;
  options.bits_per_channel = bits_per_channel;
  write_bytes(file, encode_png(image, options));
}

Image read_png(const fs::path& file) {
  FilePtr f = open_file(file, "rb");
  PngReader reader;
  PngLayout layout{};
  int channels = 0;
  char region[128] = "";
  if (!run_png_read_header(reader, f.get(), layout, channels, region)) {
    throw ImageError(std::string("libpng: ") + reader.error.text);
  }
  check_layout(layout, channels);
  const std::size_t row_bytes = png_get_rowbytes(reader.png, reader.info);
  std::vector<png_byte> bytes(row_bytes * layout.height);
  std::vector<png_bytep> rows = row_pointers(bytes, layout.height);
  if (!run_png_read_rows(reader, rows.data())) throw ImageError(std::string("libpng: ") + reader.error.text);
  Image image = image_from_rows(bytes, layout, channels);
  if (region[0] != '\0') image.region = parse_region_text(region, image.width, image.height);
  return image;
}

}  // namespace povtrace::image
