#include "parser/textures/image_location.hpp"

namespace povtrace::sdl {

std::string locate_image_file(const std::string& name, const std::vector<std::filesystem::path>& library_paths) {
  const std::filesystem::path p(name);
  if (p.is_absolute()) return name;
  std::error_code ec;   // never throws: a name the file system rejects is not found (see find_include)
  std::vector<std::filesystem::path> dirs;
  if (auto cwd = std::filesystem::current_path(ec); !ec) dirs.push_back(std::move(cwd));
  for (const auto& d : library_paths) dirs.push_back(d);
  for (const auto& d : dirs)
    if (std::filesystem::is_regular_file(d / p, ec)) return (d / p).string();
  return name;
}

}  // namespace povtrace::sdl
