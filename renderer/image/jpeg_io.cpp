// libjpeg reports errors through error_exit, which must not return: it longjmps back to the setjmp in the small
// function that made the failing call. Those functions own no C++ objects, so no destructor is skipped.
#include "renderer/image/jpeg_io.hpp"

#include <algorithm>
#include <csetjmp>
#include <cstdio>
#include <cstdlib>
#include <vector>

// jpeglib.h needs size_t and FILE declared first.
#include <jpeglib.h>

#include "renderer/image/display_encode.hpp"

namespace povtrace::image {
namespace {

constexpr int default_quality = 85;
constexpr std::uint64_t max_pixels = std::uint64_t(1) << 26;
constexpr char comment[] = "Software: povtrace\n";

struct JpegError {
  jpeg_error_mgr manager{};
  std::jmp_buf jump{};
  char text[JMSG_LENGTH_MAX] = "unknown libjpeg error";
};

void on_jpeg_error(j_common_ptr info) {
  auto* error = reinterpret_cast<JpegError*>(info->err);
  (*info->err->format_message)(info, error->text);
  std::longjmp(error->jump, 1);
}

void on_jpeg_message(j_common_ptr) {}  // warnings are not failures

struct Compressor {
  JpegError error;
  jpeg_compress_struct info{};
  unsigned char* buffer = nullptr;
  unsigned long size = 0;

  Compressor() {
    info.err = jpeg_std_error(&error.manager);
    error.manager.error_exit = on_jpeg_error;
    error.manager.output_message = on_jpeg_message;
  }
  ~Compressor() {
    jpeg_destroy_compress(&info);
    std::free(buffer);
  }
  Compressor(const Compressor&) = delete;
  Compressor& operator=(const Compressor&) = delete;
};

bool run_compress(Compressor& c, int width, int height, int quality, unsigned char* pixels) {
  if (setjmp(c.error.jump)) return false;
  jpeg_create_compress(&c.info);
  jpeg_mem_dest(&c.info, &c.buffer, &c.size);
  c.info.image_width = static_cast<JDIMENSION>(width);
  c.info.image_height = static_cast<JDIMENSION>(height);
  c.info.input_components = 3;
  c.info.in_color_space = JCS_RGB;
  jpeg_set_defaults(&c.info);
  jpeg_set_colorspace(&c.info, JCS_YCbCr);
  jpeg_set_quality(&c.info, quality, TRUE);
  c.info.comp_info[0].h_samp_factor = 1;  // no chroma subsampling, as POV-Ray
  c.info.comp_info[0].v_samp_factor = 1;
  jpeg_start_compress(&c.info, TRUE);
  jpeg_write_marker(&c.info, JPEG_COM, reinterpret_cast<const JOCTET*>(comment), sizeof comment - 1);
  const std::size_t stride = static_cast<std::size_t>(width) * 3;
  while (c.info.next_scanline < c.info.image_height) {
    JSAMPROW row = pixels + c.info.next_scanline * stride;
    jpeg_write_scanlines(&c.info, &row, 1);
  }
  jpeg_finish_compress(&c.info);
  return true;
}

struct Decompressor {
  JpegError error;
  jpeg_decompress_struct info{};

  Decompressor() {
    info.err = jpeg_std_error(&error.manager);
    error.manager.error_exit = on_jpeg_error;
    error.manager.output_message = on_jpeg_message;
  }
  ~Decompressor() { jpeg_destroy_decompress(&info); }
  Decompressor(const Decompressor&) = delete;
  Decompressor& operator=(const Decompressor&) = delete;
};

bool run_read_header(Decompressor& d, const std::string& bytes) {
  if (setjmp(d.error.jump)) return false;
  jpeg_create_decompress(&d.info);
  jpeg_mem_src(&d.info, reinterpret_cast<const unsigned char*>(bytes.data()), static_cast<unsigned long>(bytes.size()));
  jpeg_read_header(&d.info, TRUE);
  d.info.out_color_space = JCS_RGB;
  jpeg_start_decompress(&d.info);
  return true;
}

bool run_read_rows(Decompressor& d, unsigned char* pixels) {
  if (setjmp(d.error.jump)) return false;
  const std::size_t stride = static_cast<std::size_t>(d.info.output_width) * 3;
  while (d.info.output_scanline < d.info.output_height) {
    JSAMPROW row = pixels + d.info.output_scanline * stride;
    jpeg_read_scanlines(&d.info, &row, 1);
  }
  jpeg_finish_decompress(&d.info);
  return true;
}

}  // namespace

int jpeg_quality_for(int compression) {
  const int quality = std::clamp(compression, 0, 100);
  return quality <= 1 ? default_quality : quality;
}

std::string encode_jpeg(const Image& image, const EncodeOptions& options) {
  SampleLayout layout;
  layout.curve = TransferCurve::from_file_gamma(options.file_gamma);
  const std::vector<std::uint16_t> samples = encode_samples(image, layout);  // POV-Ray never dithers JPEG
  std::vector<unsigned char> pixels(samples.begin(), samples.end());
  Compressor compressor;
  if (!run_compress(compressor, image.width, image.height, jpeg_quality_for(options.jpeg_quality), pixels.data())) {
    throw ImageError(std::string("libjpeg: ") + compressor.error.text);
  }
  return {reinterpret_cast<const char*>(compressor.buffer), compressor.size};
}

Image decode_jpeg(const std::string& bytes) {
  Decompressor decompressor;
  if (!run_read_header(decompressor, bytes)) throw ImageError(std::string("libjpeg: ") + decompressor.error.text);
  const auto width = static_cast<int>(decompressor.info.output_width);
  const auto height = static_cast<int>(decompressor.info.output_height);
  if (decompressor.info.output_components != 3 || width <= 0 || height <= 0 ||
      std::uint64_t(width) * std::uint64_t(height) > max_pixels) {
    throw ImageError("unsupported JPEG layout");
  }
  std::vector<unsigned char> pixels(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3);
  if (!run_read_rows(decompressor, pixels.data())) throw ImageError(std::string("libjpeg: ") + decompressor.error.text);
  Image image(width, height);
  image.encoding = Encoding::encoded;
  for (std::size_t i = 0; i < pixels.size(); ++i) image.rgba[i / 3 * 4 + i % 3] = pixels[i] / 255.0f;
  return image;
}

}  // namespace povtrace::image
