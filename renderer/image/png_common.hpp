// What the PNG writer and the two PNG readers share: libpng's error hand-over and RAII holders for the C handles.
// libpng reports errors by longjmp: every libpng call that can fail runs inside a small function that calls setjmp
// and owns no C++ objects, so a longjmp never skips a destructor.
#pragma once

#include <png.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <string>

#include "renderer/image/image.hpp"

namespace povtrace::image::png_detail {

// Where libpng's error callback leaves its message before jumping back.
struct PngErrorText {
  char text[256] = "unknown libpng error";
};

inline void on_png_error(png_structp png, png_const_charp message) {
  auto* error = static_cast<PngErrorText*>(png_get_error_ptr(png));
  std::snprintf(error->text, sizeof error->text, "%s", message);
  png_longjmp(png, 1);
}

inline void on_png_warning(png_structp, png_const_charp) {}  // warnings (e.g. unknown chunks) are not failures

struct FileCloser {
  void operator()(std::FILE* f) const { std::fclose(f); }
};
using FilePtr = std::unique_ptr<std::FILE, FileCloser>;

inline FilePtr open_file(const std::filesystem::path& file, const char* mode) {
  FilePtr f(std::fopen(file.c_str(), mode));
  if (!f) throw ImageError(std::string("cannot open the file: ") + std::strerror(errno));
  return f;
}

struct PngReader {
  PngErrorText error;
  png_structp png = nullptr;
  png_infop info = nullptr;

  PngReader() {
    png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &error, on_png_error, on_png_warning);
    if (png != nullptr) info = png_create_info_struct(png);
    if (info == nullptr) {
      png_destroy_read_struct(&png, nullptr, nullptr);
      throw ImageError("libpng: out of memory");
    }
  }
  ~PngReader() { png_destroy_read_struct(&png, &info, nullptr); }
  PngReader(const PngReader&) = delete;
  PngReader& operator=(const PngReader&) = delete;
};

}  // namespace povtrace::image::png_detail
