// Framebuffer and image files. The renderer produces linear, unclamped RGBA floats; encoding to a file format
// is separate from shading (STYLE.md (a) step 6). Writers follow POV-Ray 3.7's encodings
// (povray-pixel-pipeline.md §6).
#pragma once

#include <cstddef>
#include <filesystem>
#include <iosfwd>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace povtrace::image {

struct ImageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// How the stored numbers relate to light: `linear` (EXR, and every render) or `encoded` (PNG/PPM values as
// stored in the file, normalised to [0,1], i.e. sRGB- or gamma-encoded).
enum class Encoding { linear, encoded };

// A rectangle of pixels, bounds inclusive: columns x0…x1, rows y0…y1 (y = 0 top row).
struct PixelRect {
  int x0 = 0, y0 = 0, x1 = -1, y1 = -1;
  int width() const { return x1 - x0 + 1; }
  int height() const { return y1 - y0 + 1; }
  bool empty() const { return x1 < x0 || y1 < y0; }
  bool contains(int x, int y) const { return x >= x0 && x <= x1 && y >= y0 && y <= y1; }
  friend bool operator==(const PixelRect&, const PixelRect&) = default;
};

struct Image {
  int width = 0;
  int height = 0;
  bool has_alpha = false;       // false: alpha is 1 everywhere and writers emit RGB only
  Encoding encoding = Encoding::linear;
  std::vector<float> rgba;      // 4 floats per pixel, row-major, top row first; colour premultiplied by alpha
  // A region render (+SR +ER +SC +EC): the rendered rectangle of this full-size image. EXR and PNG files keep it
  // (header attribute / text chunk "povtrace:region" = "x0 y0 x1 y1 width height") so `povtrace --assemble` can
  // merge parts; other formats drop it.
  std::optional<PixelRect> region;

  Image() = default;
  Image(int w, int h) : width(w), height(h), rgba(static_cast<std::size_t>(w) * h * 4, 0.0f) {
    for (std::size_t i = 3; i < rgba.size(); i += 4) rgba[i] = 1.0f;
  }
  float* pixel(int x, int y) { return &rgba[(static_cast<std::size_t>(y) * width + x) * 4]; }
  const float* pixel(int x, int y) const { return &rgba[(static_cast<std::size_t>(y) * width + x) * 4]; }
};

// POV-Ray 3.7's +F types: N png, E exr, P ppm, T tga, C tga_rle (compressed TGA), J jpeg, B bmp, H hdr (Radiance).
enum class FileFormat { png, exr, ppm, tga, tga_rle, jpeg, bmp, hdr };

// Dither_Method (+TH): POV-Ray 3.7's B2 B3 B4 (ordered), D1 D2 (error diffusion), FS (Floyd-Steinberg).
enum class Dither { none, bayer2, bayer3, bayer4, diffusion1d, diffusion2d, floyd_steinberg };

struct EncodeOptions {
  FileFormat format = FileFormat::png;
  int bits_per_channel = 8;     // PNG and PPM: 5 to 16 (POV-Ray's Bits_Per_Color)
  bool exr_full_float = false;  // EXR: 32-bit float instead of POV-Ray's half
  bool grayscale = false;       // Grayscale_Output / +F…G (PNG and PPM)
  int jpeg_quality = 0;         // Compression (JPEG quality; POV-Ray's default 0, like 1, means 85)
  std::optional<double> file_gamma;  // File_Gamma: a power; nullopt = sRGB (POV-Ray 3.7's default)
  Dither dither = Dither::none; // Dither / Dither_Method
};

// The format named by a file's extension (.png, .exr, .ppm/.pgm, .tga, .bmp, .hdr, .jpg/.jpeg; case-insensitive),
// if any. .tga names uncompressed Targa (POV-Ray names compressed Targa .tga too).
std::optional<FileFormat> format_from_extension(const std::filesystem::path& path);

// The output path meaning standard output (POV-Ray's +O-).
inline const std::filesystem::path standard_output_path{"-"};

// Writes `image` (linear) to `path`: to a temporary file in the same folder, then renamed over `path`, so a
// failure never leaves a partial file and never destroys an existing one. For `standard_output_path`, as
// write_image_to(std::cout). Throws ImageError.
void write_image(const Image& image, const std::filesystem::path& path, const EncodeOptions& options);

// Encodes the whole file in memory, then writes it to `out` at once: a failure writes nothing. Only the formats
// POV-Ray writes to standard output (PNG, PPM, TGA, BMP, HDR); EXR and JPEG throw ImageError.
void write_image_to(std::ostream& out, const Image& image, const EncodeOptions& options);

// The whole file for `image` in any format but EXR. Throws ImageError.
std::string encode_image(const Image& image, const EncodeOptions& options);

// Reads an EXR or HDR (linear) or PNG/PPM/PGM/TGA/BMP/JPEG (encoded) file, recognised by its first bytes.
// Throws ImageError for a missing or unreadable file.
Image read_image(const std::filesystem::path& path);

// Image::region as text ("x0 y0 x1 y1 width height") and back; parsing checks the recorded full size against the
// file's (ImageError if it is malformed or differs).
std::string region_text(const PixelRect& region, int width, int height);
PixelRect parse_region_text(const std::string& text, int width, int height);
inline constexpr const char* region_key = "povtrace:region";

// sRGB transfer curve (IEC 61966-2-1), POV-Ray's default File_Gamma.
double srgb_encode(double linear);
double srgb_decode(double encoded);

// The same image with colour values in linear light (encoded images are sRGB-decoded).
Image to_linear(const Image& image);

}  // namespace povtrace::image
