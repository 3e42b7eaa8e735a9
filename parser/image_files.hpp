// Image file specifications shared by height_field, image_map and bump_map (POV-Ray's Parse_Image): the file type
// keywords and the extension a file name without one is typed by.
#pragma once

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>
#include <string_view>

namespace povtrace::sdl {

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
