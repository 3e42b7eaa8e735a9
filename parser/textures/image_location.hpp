// Where an image file named in the scene is read from: shared by image_map/bump_map (image_map.cpp) and
// height_field (height_field.cpp).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace povtrace::sdl {

// `name` as written when absolute; else the first regular file `name` under the working directory or a library path
// (+L), in that order; else `name` as written (the caller reports the file missing).
std::string locate_image_file(const std::string& name, const std::vector<std::filesystem::path>& library_paths);

}  // namespace povtrace::sdl
