// Where a data file named in the scene is read from: image files for image_map/bump_map (image_map.cpp) and
// height_field (height_field.cpp), density files for density_file (pigments.cpp).
#pragma once

#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace povtrace::sdl {

// `name` as written when absolute; else the first regular file `name` under the working directory or a library path
// (+L), in that order; else `name` as written (the caller reports the file missing).
std::string locate_image_file(const std::string& name, const std::vector<std::filesystem::path>& library_paths);

// POV-Ray 3.7's search for a file of a type with known extensions (SceneData::FindFile, frontend FindFilePath):
// the candidate names are `name` itself first when it already ends in one of `extensions`, then `name` with each
// extension appended, then `name` itself last when it did not end in one; each candidate is looked for as
// locate_image_file looks (working directory, then the library paths) before the next. Nothing found: nullopt.
std::optional<std::string> locate_typed_file(const std::string& name, std::span<const std::string_view> extensions,
                                             const std::vector<std::filesystem::path>& library_paths);

}  // namespace povtrace::sdl
