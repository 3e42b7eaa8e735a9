// The density_file pattern (POV-Ray 3.7's density_pattern): POV-Ray's own values for the two files of
// scenes/pattern_density_file.pov, and the lookups' rules on small grids built here.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <limits>

#include "runtime/density_file.hpp"
#include "renderer/pattern/pattern.hpp"
#include "renderer/pattern/render_pigment.hpp"
#include "renderer/tracer.hpp"

namespace povtrace::render {
namespace {

double density_value(const std::shared_ptr<const DensityGrid>& grid, int interpolation, Vec3 p) {
  PatternParams params;
  params.kind = PatternKind::density_file;
  params.density_file = grid;
  params.density_interpolation = interpolation;
  return pattern_value(params, p);
}

// A grid of 8-bit voxels, x fastest.
std::shared_ptr<const DensityGrid> grid_of(std::size_t x, std::size_t y, std::size_t z, std::vector<std::uint8_t> v) {
  auto g = std::make_shared<DensityGrid>();
  g->size_x = x;
  g->size_y = y;
  g->size_z = z;
  g->voxels = std::move(v);
  return g;
}

std::shared_ptr<const DensityGrid> scene_file(const std::string& name) {
  const char* source = std::getenv("POVTRACE_SOURCE_DIR");
  if (source == nullptr) return nullptr;
  return std::make_shared<const DensityGrid>(
      df3::read_density_file(std::filesystem::path(source) / "scenes" / name));
}

struct PovRayValues {
  Vec3 point;
  double nearest, trilinear, tricubic;
};

// POV-Ray 3.7.0.10's values of function { pattern { density_file df3 NAME interpolate N } } at these points, printed
// with str(V, 0, 17): 17 decimals, so 1e-16 apart at most. The first point lies in the first cell on every axis,
// where the tricubic wraps as POV-Ray does; a double-precision cubic would be off by about 1e-8.
void expect_povray_values(const std::string& name, const std::vector<PovRayValues>& values) {
  const auto grid = scene_file(name);
  if (!grid) GTEST_SKIP() << "POVTRACE_SOURCE_DIR not set";
  for (const auto& v : values) {
    EXPECT_NEAR(density_value(grid, 0, v.point), v.nearest, 1e-16) << name << " nearest at " << v.point.x;
    EXPECT_NEAR(density_value(grid, 1, v.point), v.trilinear, 1e-16) << name << " trilinear at " << v.point.x;
    EXPECT_NEAR(density_value(grid, 2, v.point), v.tricubic, 1e-16) << name << " tricubic at " << v.point.x;
  }
}

TEST(DensityFilePattern, EightBitFileMatchesPovRay) {
  expect_povray_values("pattern_density_file_8.df3", {
      {{0.050, 0.030, 0.020}, 0.00000000000000000, 0.11985058823529413, 0.02595771849155426},
      {{0.310, 0.470, 0.660}, 0.10196078431372549, 0.67738423529411762, 0.76655912399291992},
      {{0.600, 0.500, 0.250}, 0.03529411764705882, 0.58823529411764708, 0.63529407978057861},
      {{0.970, 0.990, 0.900}, 0.81176470588235294, 0.47173019607843153, 0.49723416566848755},
      {{0.123, 0.876, 0.500}, 0.87058823529411766, 0.47475772549019607, 0.44365659356117249},
      {{0.700, 0.010, 0.990}, 0.34509803921568627, 0.37119137254901963, 0.37044662237167358},
      {{0.200, 0.200, 0.200}, 0.70980392156862748, 0.49584313725490198, 0.50310349464416504},
      {{0.550, 0.350, 0.150}, 0.29411764705882354, 0.53536764705882356, 0.59985762834548950},
  });
}

TEST(DensityFilePattern, SixteenBitFileMatchesPovRay) {
  expect_povray_values("pattern_density_file_16.df3", {
      {{0.050, 0.030, 0.020}, 0.50000762951094835, 0.63599461966887938, 0.65691316127777100},
      {{0.310, 0.470, 0.660}, 0.33519493400473027, 0.75669393698023946, 0.85881018638610840},
      {{0.600, 0.500, 0.250}, 0.47350270847638665, 0.50401922636758978, 0.48273563385009766},
      {{0.970, 0.990, 0.900}, 0.45250629434653239, 0.50496523079270617, 0.49710884690284729},
      {{0.123, 0.876, 0.500}, 0.37082475013351646, 0.51919576775768672, 0.59271150827407837},
      {{0.700, 0.010, 0.990}, 0.83717097734035251, 0.25604078431372523, 0.21308812499046326},
      {{0.200, 0.200, 0.200}, 0.87689021133745326, 0.57540367742427712, 0.60063439607620239},
      {{0.550, 0.350, 0.150}, 0.08813611047531854, 0.41787289234760056, 0.35619226098060608},
  });
}

// Four voxels along x: 0, 85, 170, 255 (0, 1/3, 2/3, 1).
std::shared_ptr<const DensityGrid> ramp() { return grid_of(4, 1, 1, {0, 85, 170, 255}); }

TEST(DensityFilePattern, NearestTakesTheVoxelWhoseCellHoldsThePoint) {
  EXPECT_EQ(density_value(ramp(), 0, {0.2499, 0.5, 0.5}), 0.0);
  EXPECT_EQ(density_value(ramp(), 0, {0.25, 0.5, 0.5}), 85.0 / 255.0);
  EXPECT_EQ(density_value(ramp(), 0, {0.999, 0.999, 0}), 1.0);
}

// Voxel i sits at i / size, the lower corner of its cell; after the last voxel the lookup wraps to the first.
TEST(DensityFilePattern, TrilinearPutsEachVoxelAtItsCellsLowerCorner) {
  EXPECT_EQ(density_value(ramp(), 1, {0.25, 0, 0}), 85.0 / 255.0);
  EXPECT_DOUBLE_EQ(density_value(ramp(), 1, {0.375, 0, 0}), 0.5 * (85.0 + 170.0) / 255.0);
  EXPECT_DOUBLE_EQ(density_value(ramp(), 1, {0.875, 0, 0}), 0.5);   // halfway from 255 back to voxel 0
}

TEST(DensityFilePattern, TricubicPassesThroughTheVoxels) {
  EXPECT_EQ(density_value(ramp(), 2, {0.5, 0.3, 0.7}), static_cast<double>(static_cast<float>(170.0 / 255.0)));
}

// Below the first voxel POV-Ray takes voxel (2^64 − 1) % size: the last one for size 4, voxel 0 for size 5. With
// voxels 1, 1, 1, (1,) 0 the cubic halfway through cell 0 is 1 when the voxel before it is 1 and 1.0625 when it is 0.
TEST(DensityFilePattern, TricubicWrapsBelowTheFirstVoxelAsPovRay) {
  EXPECT_EQ(density_value(grid_of(5, 1, 1, {255, 255, 255, 255, 0}), 2, {0.1, 0, 0}), 1.0);
  EXPECT_EQ(density_value(grid_of(4, 1, 1, {255, 255, 255, 0}), 2, {0.125, 0, 0}), 1.0625);
  // The same along y and z (size 6: voxel 3 instead of 5; size 10: voxel 5 instead of 9).
  EXPECT_EQ(density_value(grid_of(1, 6, 1, {255, 255, 255, 0, 255, 255}), 2, {0, 0.5 / 6, 0}), 1.0625);
  std::vector<std::uint8_t> ten(10, 255);
  ten[5] = 0;
  EXPECT_EQ(density_value(grid_of(1, 1, 10, ten), 2, {0, 0, 0.05}), 1.0625);
}

// A negative cubic becomes 0; one above 1 is kept (the wave step wraps it).
TEST(DensityFilePattern, TricubicUndershootIsZeroAndOvershootIsKept) {
  EXPECT_EQ(density_value(grid_of(5, 1, 1, {0, 0, 255, 0, 0}), 2, {0.3, 0, 0}), 0.5625);
  EXPECT_EQ(density_value(grid_of(5, 1, 1, {0, 0, 255, 0, 0}), 2, {0.7, 0, 0}), 0.0);   // −0.0625
  EXPECT_EQ(density_value(grid_of(5, 1, 1, {0, 255, 255, 0, 0}), 2, {0.3, 0, 0}), 1.125);
}

// interpolate N picks by N % 10 with C++'s (truncating) remainder: 0 nearest, 1 trilinear, anything else tricubic.
TEST(DensityFilePattern, InterpolationIsPickedByTheRemainderOfTen) {
  const auto g = grid_of(4, 1, 1, {0, 40, 200, 90});
  const Vec3 p{0.3, 0, 0};
  const double nearest = density_value(g, 0, p), trilinear = density_value(g, 1, p), tricubic = density_value(g, 2, p);
  EXPECT_EQ(nearest, 40.0 / 255.0);
  EXPECT_NE(trilinear, nearest);
  EXPECT_NE(tricubic, trilinear);
  EXPECT_EQ(density_value(g, 10, p), nearest);
  EXPECT_EQ(density_value(g, 11, p), trilinear);
  EXPECT_EQ(density_value(g, 3, p), tricubic);
  EXPECT_EQ(density_value(g, -1, p), tricubic);
  EXPECT_EQ(density_value(g, -10, p), nearest);
}

TEST(DensityFilePattern, OutsideTheUnitCubeIsZero) {
  const auto g = grid_of(1, 1, 1, {255});
  for (int mode : {0, 1, 2}) {
    EXPECT_EQ(density_value(g, mode, {0, 0, 0}), 1.0);
    EXPECT_EQ(density_value(g, mode, {1.0, 0.5, 0.5}), 0.0);
    EXPECT_EQ(density_value(g, mode, {0.5, -1e-300, 0.5}), 0.0);
    EXPECT_EQ(density_value(g, mode, {0.5, 0.5, std::numeric_limits<double>::quiet_NaN()}), 0.0);
  }
  EXPECT_EQ(density_value(grid_of(0, 3, 3, {}), 1, {0.5, 0.5, 0.5}), 0.0);   // a grid with no voxels
}

// As a pigment: the pattern's transforms, the default grey map, and the wave step wrapping a value above 1.00001.
TEST(DensityFilePattern, APigmentMapsTheValueThroughItsColourMap) {
  Pigment p;
  p.pattern = PatternKind::density_file;
  p.density_file = ramp();
  p.density_interpolation = 1;
  p.world_from_pattern = Matrix::scaling({2, 2, 2});
  const RenderPigment r = build_render_pigment(p);
  EXPECT_NEAR(evaluate_pigment(r, {0.75, 0, 0}).g, 0.5 * (85.0 + 170.0) / 255.0, 1e-7);   // pattern x 0.375
  EXPECT_EQ(evaluate_pigment(r, {2.5, 0, 0}).g, 0.0);                                     // outside: 0
  p.density_file = grid_of(5, 1, 1, {0, 255, 255, 0, 0});
  p.density_interpolation = 2;
  p.world_from_pattern = Matrix::identity();
  EXPECT_NEAR(evaluate_pigment(build_render_pigment(p), {0.3, 0, 0}).g, std::fmod(1.125, 1.00001), 1e-7);
}

}  // namespace
}  // namespace povtrace::render
