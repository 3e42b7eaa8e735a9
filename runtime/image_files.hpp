// Image file specifications shared by height_field, image_map and bump_map (POV-Ray's Parse_Image): the file type
// keywords and the extension a file name without one is typed by.
#pragma once

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace povtrace::sdl {

// A value as POV-Ray's 16-bit function images hold it (Make_Pattern_Image, for `function W, H { … }` height
// fields): stored as unsigned short(v · 65535) of the float v, unclipped — C++ leaves an out-of-range conversion
// undefined, and POV-Ray's x86-64 build converts through a 32-bit integer and keeps its low 16 bits, so values
// outside [0, 1] wrap (a NaN becomes 0) — and read back as stored / 65535 in float.
inline float function_image_value(double v) {
  const float scaled = static_cast<float>(v) * 65535.0f;
  const std::int32_t wide =
      std::isfinite(scaled) && std::fabs(scaled) < 2147483520.0f ? static_cast<std::int32_t>(scaled) : 0;
  return static_cast<float>(static_cast<std::uint32_t>(wide) & 0xffffu) / 65535.0f;
}

inline bool is_image_type_word(std::string_view w) {
  static constexpr std::string_view types[] = {"iff", "gif", "pot", "sys", "tga", "png", "pgm",
                                               "ppm", "jpeg", "tiff", "bmp", "exr", "hdr"};
  return std::find(std::begin(types), std::end(types), w) != std::end(types);
}

// The file name's extension in lower case, with its dot ("" when there is none).
inline std::string lower_extension(const std::string& name) {
  std::string ext = std::filesystem::path(name).extension().string();
  for (auto& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

}  // namespace povtrace::sdl
