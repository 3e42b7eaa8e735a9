// The density_file pattern, as POV-Ray 3.7's density_pattern computes it (source/backend/pattern/pattern.cpp,
// 3.7-stable; checked against POV-Ray 3.7.0.10's values of function { pattern { density_file … } }):
// - The grid covers the unit cube: a point is inside when 0 ≤ x, y, z < 1; outside (and with a grid of no voxels)
//   the value is 0.
// - interpolate N with N % 10 = 0: the voxel at (size_t)(x · size_x), … — voxel i covers [i, i + 1) / size.
// - N % 10 = 1: trilinear between voxel i and i + 1 (wrapping to 0 after the last), voxel i's value sitting at
//   i / size: the lower corner of its cell, not its centre.
// - any other N (POV-Ray's default branch, negative N too): tricubic, Catmull-Rom in z, then y, then x, over
//   voxels i − 1 … i + 2, in single precision, with POV-Ray's wrapping quirk at the low edge (neighbour_index).
// - A negative result (the tricubic's undershoot) becomes 0; one above 1 is kept (the wave step then wraps it).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include "runtime/density_file.hpp"
#include "renderer/pattern/pattern_functions.hpp"

namespace povtrace::render::patterns {

namespace {
double voxel(const DensityGrid& g, std::size_t x, std::size_t y, std::size_t z) {
  return df3::voxel_value(g, (z * g.size_y + y) * g.size_x + x);
}

std::size_t cell_of(double c, std::size_t size) {
  // c·size < size for every c < 1 in double arithmetic, so the clamp never changes a cell; it only keeps the
  // lookup inside the grid whatever the rounding.
  return std::min(static_cast<std::size_t>(c * static_cast<double>(size)), size - 1);
}

double nearest(const DensityGrid& g, Vec3 p) {
  return voxel(g, cell_of(p.x, g.size_x), cell_of(p.y, g.size_y), cell_of(p.z, g.size_z));
}

// One axis of the trilinear lookup: the cell, the next one (wrapping) and the position between them.
struct Span {
  std::size_t lo, hi;
  double t;
};
Span span(double c, std::size_t size) {
  const double scaled = c * static_cast<double>(size);
  const std::size_t lo = cell_of(c, size);
  return {lo, (lo + 1) % size, scaled - std::floor(scaled)};
}

// POV-Ray's order of operations, for identical rounding.
double trilinear(const DensityGrid& g, Vec3 p) {
  const Span x = span(p.x, g.size_x), y = span(p.y, g.size_y), z = span(p.z, g.size_z);
  const double xi = 1.0 - x.t, yi = 1.0 - y.t;
  auto along_x = [&](std::size_t yy, std::size_t zz) {
    return voxel(g, x.lo, yy, zz) * xi + voxel(g, x.hi, yy, zz) * x.t;
  };
  return (along_x(y.lo, z.lo) * yi + along_x(y.hi, z.lo) * y.t) * (1.0 - z.t) +
         (along_x(y.lo, z.hi) * yi + along_x(y.hi, z.hi) * y.t) * z.t;
}

// Catmull-Rom from fb (t = 0) to fc (t = 1) as POV-Ray's intp3 computes it: float arguments, the coefficients
// computed in double and stored as float, the cubic evaluated in float.
float catmull_rom(float t, float fa, float fb, float fc, float fd) {
  const float b = static_cast<float>((fc - fa) * 0.5);
  const float d = static_cast<float>((fd - fb) * 0.5);
  const float e = static_cast<float>(2.0 * (fb - fc) + b + d);
  const float f = static_cast<float>(-3.0 * (fb - fc) - 2.0 * b - d);
  return ((e * t + f) * t + b) * t + fb;
}

// Neighbour `offset` (0 … 3 for i − 1 … i + 2) of cell i. POV-Ray computes i − 1 in its 64-bit size_t and its
// "negative means the last cell" test never holds for an unsigned value, so below cell 0 it takes (2^64 − 1) %
// size: the last cell only when size is a power of two (0 for size 5, 3 for size 6, 1 for size 7). Above the
// last cell it wraps to 0, 1.
std::size_t neighbour_index(std::size_t i, std::size_t offset, std::size_t size) {
  const std::uint64_t wrapped = std::uint64_t{i} + std::uint64_t{offset} - 1;   // unsigned: 0 − 1 wraps
  return static_cast<std::size_t>(wrapped % std::uint64_t{size});
}

double tricubic(const DensityGrid& g, Vec3 p) {
  const double sx = p.x * static_cast<double>(g.size_x), sy = p.y * static_cast<double>(g.size_y),
               sz = p.z * static_cast<double>(g.size_z);
  const std::size_t x1 = cell_of(p.x, g.size_x), y1 = cell_of(p.y, g.size_y), z1 = cell_of(p.z, g.size_z);
  const auto tx = static_cast<float>(sx - std::floor(sx)), ty = static_cast<float>(sy - std::floor(sy)),
             tz = static_cast<float>(sz - std::floor(sz));
  std::array<std::size_t, 4> zs{};
  for (std::size_t k = 0; k < 4; ++k) zs[k] = neighbour_index(z1, k, g.size_z);
  std::array<float, 4> along_y{};
  for (std::size_t i = 0; i < 4; ++i) {
    const std::size_t xx = neighbour_index(x1, i, g.size_x);
    std::array<float, 4> along_z{};
    for (std::size_t j = 0; j < 4; ++j) {
      const std::size_t yy = neighbour_index(y1, j, g.size_y);
      auto f = [&](std::size_t k) { return static_cast<float>(voxel(g, xx, yy, zs[k])); };
      along_z[j] = catmull_rom(tz, f(0), f(1), f(2), f(3));
    }
    along_y[i] = catmull_rom(ty, along_z[0], along_z[1], along_z[2], along_z[3]);
  }
  return catmull_rom(tx, along_y[0], along_y[1], along_y[2], along_y[3]);
}

bool inside_unit_cube(Vec3 p) {
  return p.x >= 0.0 && p.x < 1.0 && p.y >= 0.0 && p.y < 1.0 && p.z >= 0.0 && p.z < 1.0;
}
}  // namespace

double density_file(const DensityGrid& grid, int interpolation, Vec3 p) {
  if (grid.size_x == 0 || grid.size_y == 0 || grid.size_z == 0 || !inside_unit_cube(p)) return 0.0;
  double value = 0.0;
  switch (interpolation % 10) {   // C++'s % truncates as POV-Ray's does: −1 % 10 = −1, tricubic
    case 0: value = nearest(grid, p); break;
    case 1: value = trilinear(grid, p); break;
    default: value = tricubic(grid, p); break;
  }
  return value < 0.0 ? 0.0 : value;
}

}  // namespace povtrace::render::patterns
