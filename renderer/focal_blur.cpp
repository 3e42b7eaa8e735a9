#include "renderer/focal_blur.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "renderer/media/render_media.hpp"
#include "renderer/radiosity/directions.hpp"
#include "runtime/jitter.hpp"
#include "scene/pov_vector_math.hpp"

namespace povtrace::render {

namespace {

// POV-Ray's standard lens grids: the 4-point square (for fewer than 7 rays) and hexagonal grids of 7, 19 and 37
// points. Each is listed in POV-Ray's order as lattice steps (i, j), the point being (i · sx, j · sy) with
// sx = 1/(2k·√3), sy = 1/(2k) for k = 2, 3, 4; POV-Ray keeps six decimals of each coordinate, as computed here
// (checked once against all 63 of its points). Rays are tested for confidence in POV-Ray's batches, ring by ring.
struct LensGrid {
  double step_x, step_y;        // the lattice steps
  double max_jitter;            // POV-Ray's jitter for exactly this many rays (one x step)
  std::vector<std::pair<int, int>> points;
  std::vector<int> batches;
};

double six_decimals(double v) { return std::round(v * 1e6) / 1e6; }

const LensGrid& hex_grid(int size) {
  // Hexagon of 7: centre and the six neighbours at one lattice distance (x steps of 1/(4√3), y steps of 1/4).
  static const LensGrid g7{1.0 / (4.0 * std::sqrt(3.0)), 0.25, six_decimals(1.0 / (4.0 * std::sqrt(3.0))),
                           {{-2, 0}, {0, 0}, {2, 0}, {-1, 1}, {-1, -1}, {1, 1}, {1, -1}},
                           {7, 0}};
  // 19: the hexagon of radius 2 steps (x steps of 1/(6√3), y steps of 1/6), its centre, then two rings inside.
  static const LensGrid g19{1.0 / (6.0 * std::sqrt(3.0)), 1.0 / 6.0, six_decimals(1.0 / (6.0 * std::sqrt(3.0))),
                            {{-2, 2}, {-2, -2}, {2, 2}, {2, -2}, {4, 0}, {-4, 0}, {0, 0},
                             {0, 2}, {0, -2}, {-3, 1}, {-3, -1}, {3, 1}, {3, -1},
                             {-1, 1}, {-1, -1}, {1, 1}, {1, -1}, {-2, 0}, {2, 0}},
                            {7, 6, 6, 0}};
  // 37: x steps of 1/(8√3), y steps of 1/8; the outer hexagon and centre, two inner rings, then the points between.
  // Its jitter is written with seven decimals in POV-Ray.
  static const LensGrid g37{1.0 / (8.0 * std::sqrt(3.0)), 0.125,
                            std::round(1e7 / (8.0 * std::sqrt(3.0))) / 1e7,
                            {{0, 0},   {-3, 3},  {3, -3},  {-3, -3}, {3, 3},   {-6, 0}, {6, 0},
                             {-2, 2},  {2, -2},  {-2, -2}, {2, 2},   {-4, 0},  {4, 0},
                             {-1, 1},  {1, -1},  {-1, -1}, {1, 1},   {-2, 0},  {2, 0},
                             {-5, 1},  {-5, -1}, {5, 1},   {5, -1},
                             {-4, 2},  {-4, -2}, {4, 2},   {4, -2},
                             {-1, 3},  {-1, -3}, {1, 3},   {1, -3},
                             {-3, 1},  {-3, -1}, {3, 1},   {3, -1},
                             {0, 2},   {0, -2}},
                            {7, 6, 6, 4, 4, 4, 4, 2, 0}};
  return size == 37 ? g37 : size == 19 ? g19 : g7;
}

// Point k (from 0) of POV-Ray's sub-random sequence on the disc of radius ½ (HaltonOnDiscGenerator with bases 2
// and 3): the squared radius ¼·φ2(k+1), the angle 2π·φ3(k+1).
std::pair<double, double> halton_on_disc(std::size_t k) {
  const double r = std::sqrt(radiosity::radical_inverse(k + 1, 2) * 0.25);
  const double theta = radiosity::radical_inverse(k + 1, 3) * (2 * std::numbers::pi);
  return {r * std::cos(theta), r * std::sin(theta)};
}

// Lens points beyond the standard grid: Halton points on the disc, each in a cell of a (2⌈√(N/π)⌉ + 1)² grid not yet
// taken (while enough of the 10·N candidates are left), as POV-Ray's FocalBlurData distributes them.
void add_disc_points(std::vector<std::pair<double, double>>& grid, int standard, int samples) {
  const int size = 2 * static_cast<int>(std::ceil(std::sqrt(samples / std::numbers::pi))) + 1;
  std::vector<char> taken(static_cast<std::size_t>(size) * size, 0);
  const auto cell = [size](double v) { return std::min(static_cast<int>((v + 0.5) * size), size - 1); };
  for (int i = 0; i < standard; ++i) {
    const int xi = static_cast<int>((grid[static_cast<std::size_t>(i)].first + 0.5) * size);
    const int yi = static_cast<int>((grid[static_cast<std::size_t>(i)].second + 0.5) * size);
    ++taken[static_cast<std::size_t>(yi) * size + xi];
  }
  std::size_t remain = static_cast<std::size_t>(samples) * 10, next = 0;
  for (int i = standard; i < samples; ++i) {
    auto v = halton_on_disc(next++);
    int xi = cell(v.first), yi = cell(v.second);
    --remain;
    while ((taken[static_cast<std::size_t>(yi) * size + xi] || v.first * v.first + v.second * v.second > 0.25) &&
           remain > static_cast<std::size_t>(samples - i)) {
      v = halton_on_disc(next++);
      xi = cell(v.first);
      yi = cell(v.second);
      --remain;
    }
    grid.push_back(v);
    ++taken[static_cast<std::size_t>(yi) * size + xi];
  }
}

}  // namespace

std::optional<FocalBlurSetup> make_focal_blur(const Camera& camera) {
  const FocalBlur& f = camera.focal_blur;
  if (f.aperture == 0.0 || f.samples <= 0 || camera.projection == Projection::mesh) return std::nullopt;
  FocalBlurSetup b;
  b.aperture = f.aperture;
  b.samples = f.samples;
  b.min_samples = f.min_samples;
  // The confidence thresholds: variance / chdtri(N − 1, confidence) · chdtri(n, confidence) for n = 1 … N.
  b.thresholds.assign(static_cast<std::size_t>(f.samples), 0.0);
  if (f.samples > 1) {
    const double t1 = f.variance / inverse_chi_square_complement(f.samples - 1, f.confidence);
    for (int i = 0; i < f.samples; ++i)
      b.thresholds[static_cast<std::size_t>(i)] = t1 * inverse_chi_square_complement(i + 1, f.confidence);
  }
  // The standard grid: the largest hexagonal one that fits, else the 4-point square.
  int standard = 4;
  if (f.samples >= 7) {
    const int size = f.samples >= 37 ? 37 : f.samples >= 19 ? 19 : 7;
    const LensGrid& g = hex_grid(size);
    for (const auto& [i, j] : g.points) b.grid.emplace_back(six_decimals(i * g.step_x), six_decimals(j * g.step_y));
    b.batches = g.batches;
    standard = size;
  } else {
    for (const auto& p : {std::pair{-0.25, 0.25}, std::pair{0.25, 0.25}, std::pair{-0.25, -0.25}, std::pair{0.25, -0.25}})
      if (static_cast<int>(b.grid.size()) < f.samples) b.grid.push_back(p);
  }
  b.max_jitter = f.samples == 7 || f.samples == 19 || f.samples == 37 ? hex_grid(f.samples).max_jitter
                                                                     : 0.5 / std::sqrt(static_cast<double>(f.samples));
  if (f.samples > standard) add_disc_points(b.grid, standard, f.samples);
  // The lens plane: x ⟂ up and direction, y ⟂ direction and x (POV-Ray's XPerp, YPerp).
  b.location = camera.location;
  b.x_perp = pov_normalized(cross(camera.up, camera.direction));
  b.y_perp = pov_normalized(cross(camera.direction, b.x_perp));
  b.focal_scale = f.focal_distance / length(camera.direction);
  return b;
}

void jitter_lens(const FocalBlurSetup& blur, double x, double y, int ray_number, Vec3& origin, Vec3& direction) {
  const double r = blur.aperture * 0.5;
  auto [jx, jy] = povray_jitter2d(x, y);
  jx *= blur.max_jitter * 2.0;
  jy *= blur.max_jitter * 2.0;
  const auto& [gx, gy] = blur.grid[static_cast<std::size_t>(ray_number)];
  const double xlen = r * (gx + jx), ylen = r * (gy + jy);
  const Vec3 deflection = blur.x_perp * xlen - blur.y_perp * ylen;
  origin = blur.location + deflection;
  direction = direction * blur.focal_scale - deflection;
}

std::pair<double, double> focal_blur_offset(double x, double y, int n) {
  constexpr int kCells = 16;
  const int seed = static_cast<int>(x * 313.0 + 11.0) + static_cast<int>(y * 311.0 + 17.0);
  const int dxi = lattice_permutation_entry(seed + n) % kCells;
  const int dyi = lattice_permutation_entry(seed + n + 1) % kCells;
  double dx = static_cast<double>(2 * dxi + 1) / static_cast<double>(2 * kCells) - 0.5;
  double dy = static_cast<double>(2 * dyi + 1) / static_cast<double>(2 * kCells) - 0.5;
  const auto [rx, ry] = povray_jitter2d(dx, dy);
  // POV-Ray subtracts ½ from offsets that already lie in [−½, ½): every ray moves up and left by up to 1/16.
  dx += (rx - 0.5) / static_cast<double>(kCells);
  dy += (ry - 0.5) / static_cast<double>(kCells);
  return {dx, dy};
}

}  // namespace povtrace::render
