#include "runtime/density_file.hpp"

#include <algorithm>
#include <fstream>
#include <iterator>

namespace povtrace::df3 {

namespace {
constexpr std::size_t kHeaderBytes = 6;   // three unsigned 16-bit sizes

std::size_t big_endian_u16(const std::vector<std::uint8_t>& bytes, std::size_t at) {
  return (static_cast<std::size_t>(bytes[at]) << 8) | bytes[at + 1];
}

// POV-Ray compares the voxel data's length with 4, then 2, then 1 byte per voxel. A grid with no voxels (a zero
// size) matches 4 when there is no data: POV-Ray accepts it, and the pattern is 0 everywhere.
int voxel_width(std::size_t voxel_count, std::size_t data_bytes) {
  for (const int width : {4, 2, 1})
    if (voxel_count * static_cast<std::size_t>(width) == data_bytes) return width;
  return 0;
}
}  // namespace

DensityGrid parse_density_file(std::vector<std::uint8_t> bytes, const std::string& file) {
  if (bytes.size() < kHeaderBytes)
    throw DensityFileError("the density file '" + file + "' is too short for its header (" +
                           std::to_string(bytes.size()) + " bytes; it starts with three 16-bit sizes, 6 bytes)");
  DensityGrid g;
  g.file = file;
  g.size_x = big_endian_u16(bytes, 0);
  g.size_y = big_endian_u16(bytes, 2);
  g.size_z = big_endian_u16(bytes, 4);
  const std::size_t count = g.size_x * g.size_y * g.size_z;
  const std::size_t data = bytes.size() - kHeaderBytes;
  g.bytes_per_voxel = voxel_width(count, data);
  if (g.bytes_per_voxel == 0)
    throw DensityFileError("invalid density file size: '" + file + "' has " + std::to_string(data) +
                           " bytes after its header, which is not 1, 2 or 4 bytes for each of its " +
                           std::to_string(g.size_x) + "x" + std::to_string(g.size_y) + "x" +
                           std::to_string(g.size_z) + " voxels");
  bytes.erase(bytes.begin(), bytes.begin() + static_cast<std::ptrdiff_t>(kHeaderBytes));
  g.voxels = std::move(bytes);
  return g;
}

DensityGrid read_density_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw DensityFileError("cannot open the density file '" + path.string() + "'");
  std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw DensityFileError("cannot read the density file '" + path.string() + "'");
  return parse_density_file(std::move(bytes), path.string());
}

}  // namespace povtrace::df3
