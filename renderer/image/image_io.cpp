// Format dispatch, the sRGB curve and linearisation. The format writers and readers live in exr_io, png_io,
// ppm_io, tga_io, bmp_io, hdr_io and jpeg_io; write_image adds validation and the atomic replacement of the
// destination (atomic_file), or writes the whole encoded file to standard output for the path "-".
#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

#include "renderer/image/atomic_file.hpp"
#include "renderer/image/bmp_io.hpp"
#include "renderer/image/encoded_file.hpp"
#include "renderer/image/exr_io.hpp"
#include "renderer/image/hdr_io.hpp"
#include "renderer/image/image.hpp"
#include "renderer/image/jpeg_io.hpp"
#include "renderer/image/png_io.hpp"
#include "renderer/image/ppm_io.hpp"
#include "renderer/image/tga_io.hpp"

namespace povtrace::image {
namespace {

namespace fs = std::filesystem;

// IEC 61966-2-1 constants.
constexpr double srgb_linear_limit = 0.0031308;   // encode: below this the curve is a straight line
constexpr double srgb_encoded_limit = 0.04045;    // decode: the same point on the encoded side
constexpr double srgb_slope = 12.92;
constexpr double srgb_scale = 1.055;
constexpr double srgb_offset = 0.055;
constexpr double srgb_exponent = 2.4;

std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
  return text;
}

const char* format_name(FileFormat format) {
  switch (format) {
    case FileFormat::png: return "PNG";
    case FileFormat::exr: return "EXR";
    case FileFormat::ppm: return "binary PPM (P6)";
    case FileFormat::tga: return "Targa";
    case FileFormat::tga_rle: return "compressed Targa";
    case FileFormat::jpeg: return "JPEG";
    case FileFormat::bmp: return "BMP";
    case FileFormat::hdr: return "Radiance HDR";
  }
  return "unknown";
}

void check_writable(const Image& image, const EncodeOptions& options) {
  if (image.width <= 0 || image.height <= 0) throw ImageError("the image is empty");
  if (image.rgba.size() != static_cast<std::size_t>(image.width) * image.height * 4) {
    throw ImageError("the image's pixel buffer does not match its size");
  }
  const bool variable_depth = options.format == FileFormat::png || options.format == FileFormat::ppm;
  if (variable_depth && (options.bits_per_channel < 5 || options.bits_per_channel > 16)) {
    throw ImageError("PNG and PPM take 5 to 16 bits per channel, not " + std::to_string(options.bits_per_channel));
  }
  if (options.file_gamma && !(*options.file_gamma > 0.0)) throw ImageError("File_Gamma must be positive");
}

// POV-Ray writes only these formats to standard output (imageprocessing.cpp, GetOutputFilename).
bool streamable(FileFormat format) {
  switch (format) {
    case FileFormat::hdr:
    case FileFormat::png:
    case FileFormat::tga:
    case FileFormat::tga_rle:
    case FileFormat::ppm:
    case FileFormat::bmp: return true;
    case FileFormat::exr:
    case FileFormat::jpeg: return false;
  }
  return false;
}

void write_format(const Image& image, const fs::path& file, const EncodeOptions& options) {
  if (options.format == FileFormat::exr) {
    write_exr(image.encoding == Encoding::linear ? image : to_linear(image), file, options.exr_full_float);
  } else {
    write_bytes(file, encode_image(image, options));
  }
}

// The format named by a file's first bytes, if any.
std::optional<FileFormat> format_from_magic(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ImageError("cannot read '" + path.string() + "': " + std::strerror(errno));
  std::array<unsigned char, 8> head{};
  in.read(reinterpret_cast<char*>(head.data()), head.size());
  const auto starts_with = [&](std::initializer_list<unsigned char> magic) {
    return static_cast<std::size_t>(in.gcount()) >= magic.size() &&
           std::equal(magic.begin(), magic.end(), head.begin());
  };
  if (starts_with({0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'})) return FileFormat::png;
  if (starts_with({0x76, 0x2f, 0x31, 0x01})) return FileFormat::exr;
  if (starts_with({'P', '6'}) || starts_with({'P', '5'})) return FileFormat::ppm;
  if (starts_with({'B', 'M'})) return FileFormat::bmp;
  if (starts_with({'#', '?'})) return FileFormat::hdr;
  if (starts_with({0xff, 0xd8, 0xff})) return FileFormat::jpeg;
  // Targa has no signature: an uncompressed or RLE true-colour/grey image type with no colour map.
  if (in.gcount() >= 3 && head[1] == 0 && (head[2] == 2 || head[2] == 3 || head[2] == 10 || head[2] == 11)) {
    return FileFormat::tga;
  }
  return std::nullopt;
}

Image read_format(const fs::path& path, FileFormat format) {
  switch (format) {
    case FileFormat::exr: return read_exr(path);
    case FileFormat::png: return read_png(path);
    case FileFormat::ppm: return read_ppm(path);
    case FileFormat::tga:
    case FileFormat::tga_rle: return decode_tga(read_bytes(path));
    case FileFormat::bmp: return decode_bmp(read_bytes(path));
    case FileFormat::hdr: return decode_hdr(read_bytes(path));
    case FileFormat::jpeg: return decode_jpeg(read_bytes(path));
  }
  throw ImageError("unknown file format");
}

std::string unrecognised_message(const fs::path& path) {
  const std::string message = "cannot read '" + path.string() + "': ";
  const std::optional<FileFormat> named = format_from_extension(path);
  if (!named) return message + "not a PNG, EXR, PPM, Targa, BMP, Radiance HDR or JPEG file";
  return message + "not a valid " + format_name(*named) + " file (unrecognised signature)";
}

// Encoded premultiplied colour → linear premultiplied colour, one pixel.
void linearise_pixel(float* p, bool has_alpha) {
  const double alpha = has_alpha ? p[3] : 1.0;
  for (int c = 0; c < 3; ++c) {
    p[c] = alpha > 0.0 ? static_cast<float>(srgb_decode(p[c] / alpha) * alpha) : 0.0f;
  }
}

}  // namespace

std::string region_text(const PixelRect& r, int width, int height) {
  return std::to_string(r.x0) + " " + std::to_string(r.y0) + " " + std::to_string(r.x1) + " " +
         std::to_string(r.y1) + " " + std::to_string(width) + " " + std::to_string(height);
}

PixelRect parse_region_text(const std::string& text, int width, int height) {
  std::istringstream in(text);
  PixelRect r;
  int w = 0, h = 0;
  std::string rest;
  if (!(in >> r.x0 >> r.y0 >> r.x1 >> r.y1 >> w >> h) || (in >> rest)) {
    throw ImageError(std::string("malformed ") + region_key + " '" + text + "'");
  }
  if (w != width || h != height) {
    throw ImageError(std::string(region_key) + " records a " + std::to_string(w) + "x" + std::to_string(h) +
                     " image but the file is " + std::to_string(width) + "x" + std::to_string(height));
  }
  if (r.empty() || r.x0 < 0 || r.y0 < 0 || r.x1 >= width || r.y1 >= height) {
    throw ImageError(std::string(region_key) + " '" + text + "' is not a rectangle inside the image");
  }
  return r;
}

std::optional<FileFormat> format_from_extension(const fs::path& path) {
  const std::string extension = lower(path.extension().string());
  if (extension == ".png") return FileFormat::png;
  if (extension == ".exr") return FileFormat::exr;
  if (extension == ".ppm" || extension == ".pgm") return FileFormat::ppm;
  if (extension == ".tga") return FileFormat::tga;
  if (extension == ".bmp") return FileFormat::bmp;
  if (extension == ".hdr") return FileFormat::hdr;
  if (extension == ".jpg" || extension == ".jpeg") return FileFormat::jpeg;
  return std::nullopt;
}

std::string encode_image(const Image& image, const EncodeOptions& options) {
  check_writable(image, options);
  switch (options.format) {
    case FileFormat::png: return encode_png(image, options);
    case FileFormat::ppm: return encode_ppm(image, options);
    case FileFormat::tga: return encode_tga(image, options, false);
    case FileFormat::tga_rle: return encode_tga(image, options, true);
    case FileFormat::bmp: return encode_bmp(image, options);
    case FileFormat::hdr: return encode_hdr(image, options);
    case FileFormat::jpeg: return encode_jpeg(image, options);
    case FileFormat::exr: break;
  }
  throw ImageError("EXR files are written to a path only");
}

void write_image_to(std::ostream& out, const Image& image, const EncodeOptions& options) {
  if (!streamable(options.format)) {
    throw ImageError(std::string("cannot write ") + format_name(options.format) +
                     " to standard output (only PNG, PPM, Targa, BMP and Radiance HDR, as in POV-Ray)");
  }
  const std::string bytes = encode_image(image, options);  // all of it before any byte goes out
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  out.flush();
  if (!out) throw ImageError("write error on standard output");
}

void write_image(const Image& image, const fs::path& path, const EncodeOptions& options) {
  if (path == standard_output_path) {
    try {
      write_image_to(std::cout, image, options);
    } catch (const ImageError& e) {
      throw ImageError(std::string("cannot write the image to standard output: ") + e.what());
    }
    return;
  }
  try {
    check_writable(image, options);
  } catch (const ImageError& e) {
    throw ImageError("cannot write '" + path.string() + "': " + e.what());
  }
  write_file_atomically(path, [&](const fs::path& temp) { write_format(image, temp, options); });
}

Image read_image(const fs::path& path) {
  std::error_code error;
  if (fs::is_directory(path, error)) throw ImageError("cannot read '" + path.string() + "': it is a folder");
  const std::optional<FileFormat> format = format_from_magic(path);
  if (!format) throw ImageError(unrecognised_message(path));
  try {
    return read_format(path, *format);
  } catch (const ImageError& e) {
    throw ImageError("cannot read '" + path.string() + "': " + e.what());
  }
}

double srgb_encode(double linear) {
  if (linear <= srgb_linear_limit) return srgb_slope * linear;
  return srgb_scale * std::pow(linear, 1.0 / srgb_exponent) - srgb_offset;
}

double srgb_decode(double encoded) {
  if (encoded <= srgb_encoded_limit) return encoded / srgb_slope;
  return std::pow((encoded + srgb_offset) / srgb_scale, srgb_exponent);
}

Image to_linear(const Image& image) {
  Image result = image;
  if (image.encoding == Encoding::linear) return result;
  result.encoding = Encoding::linear;
  for (std::size_t i = 0; i + 3 < result.rgba.size(); i += 4) linearise_pixel(&result.rgba[i], image.has_alpha);
  return result;
}

}  // namespace povtrace::image
