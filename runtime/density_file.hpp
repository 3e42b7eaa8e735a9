// DF3 density files (`density_file df3 "NAME"`), read as POV-Ray 3.7's Read_Density_File reads them
// (source/backend/pattern/pattern.cpp, 3.7-stable): three big-endian 16-bit sizes x, y, z, then the voxels, x
// fastest, then y, then z. The voxel width is not stored: it is 4, 2 or 1 bytes, whichever makes the voxels fill
// the rest of the file exactly (tried in that order); any other length is an error, and so is a file too short
// for its sizes. Voxels are big-endian and read as stored / (2^(8·width) − 1), so 0..1.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "scene/description.hpp"

namespace povtrace::df3 {

struct DensityFileError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The grid in `bytes`, the whole file named `file` (for messages); throws DensityFileError as described above.
DensityGrid parse_density_file(std::vector<std::uint8_t> bytes, const std::string& file);

// The file at `path` read whole and parsed; a file that cannot be read is a DensityFileError too.
DensityGrid read_density_file(const std::filesystem::path& path);

// Voxel number `index` (x + size_x · (y + size_y · z)) as POV-Ray divides it: in double precision, by the largest
// value of the voxel width (255, 65535 or 4294967295).
inline double voxel_value(const DensityGrid& g, std::size_t index) {
  const std::uint8_t* v = g.voxels.data() + index * static_cast<std::size_t>(g.bytes_per_voxel);
  switch (g.bytes_per_voxel) {
    case 4: {
      const std::uint32_t stored = (std::uint32_t{v[0]} << 24) | (std::uint32_t{v[1]} << 16) |
                                   (std::uint32_t{v[2]} << 8) | std::uint32_t{v[3]};
      return static_cast<double>(stored) / 4294967295.0;
    }
    case 2: return static_cast<double>((unsigned{v[0]} << 8) | unsigned{v[1]}) / 65535.0;
    default: return static_cast<double>(v[0]) / 255.0;
  }
}

}  // namespace povtrace::df3
