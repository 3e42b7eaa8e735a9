#include "parser/textures/image_location.hpp"

#include <algorithm>

namespace povtrace::sdl {

namespace {
// The first regular file `name` names: as written when absolute, else under the working directory or a library
// path, in that order. Every query takes an error_code: a name the file system rejects is simply not found.
std::optional<std::string> find_file(const std::string& name,
                                     const std::vector<std::filesystem::path>& library_paths) {
  const std::filesystem::path p(name);
  std::error_code ec;
  if (p.is_absolute()) {
    if (std::filesystem::is_regular_file(p, ec)) return name;
    return std::nullopt;
  }
  std::vector<std::filesystem::path> dirs;
  if (auto cwd = std::filesystem::current_path(ec); !ec) dirs.push_back(std::move(cwd));
  for (const auto& d : library_paths) dirs.push_back(d);
  for (const auto& d : dirs)
    if (std::filesystem::is_regular_file(d / p, ec)) return (d / p).string();
  return std::nullopt;
}
}  // namespace

std::string locate_image_file(const std::string& name, const std::vector<std::filesystem::path>& library_paths) {
  if (std::filesystem::path(name).is_absolute()) return name;
  return find_file(name, library_paths).value_or(name);
}

std::optional<std::string> locate_typed_file(const std::string& name, std::span<const std::string_view> extensions,
                                             const std::vector<std::filesystem::path>& library_paths) {
  const bool typed = std::any_of(extensions.begin(), extensions.end(),
                                 [&](std::string_view ext) { return name.ends_with(ext); });
  std::vector<std::string> candidates;
  if (typed) candidates.push_back(name);
  for (const std::string_view ext : extensions) candidates.push_back(name + std::string(ext));
  if (!typed) candidates.push_back(name);
  for (const auto& candidate : candidates)
    if (auto found = find_file(candidate, library_paths)) return found;
  return std::nullopt;
}

}  // namespace povtrace::sdl
