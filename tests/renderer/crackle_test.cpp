// crackle's forms, offset and neighbourhood, cells' values, and the solid form, whose shades come from povtrace's
// noise table (the cell points and cells' values are POV-Ray's own: the scene pattern_crackle matches its render).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "runtime/noise.hpp"
#include "renderer/pattern/pattern.hpp"

namespace povtrace::render {
namespace {

double value(Vec3 p, const CrackleParams& c) {
  PatternParams params;
  params.kind = PatternKind::crackle;
  params.crackle = c;
  return pattern_value(params, p);
}

// The three nearest distances (metric 2), read through the forms <1,0,0>, <0,1,0> and <0,0,1> (each clipped to
// [0, 1] like every crackle value).
std::vector<double> sorted_distances(Vec3 p) {
  std::vector<double> d;
  d.push_back(value(p, CrackleParams{{1, 0, 0}, 2, 0, false}));
  d.push_back(value(p, CrackleParams{{0, 1, 0}, 2, 0, false}));
  d.push_back(value(p, CrackleParams{{0, 0, 1}, 2, 0, false}));
  return d;
}

TEST(Crackle, DefaultFormIsSecondMinusFirstDistance) {
  for (const Vec3 p : {Vec3{0.3, 0.2, 0.7}, Vec3{-4.1, 2.5, 9.3}, Vec3{12.6, -0.4, -3.3}}) {
    const std::vector<double> d = sorted_distances(p);
    EXPECT_LE(d[0], d[1]);
    EXPECT_LE(d[1], std::max(d[2], 1.0 - 1e-15) + 1e-15);   // d3 is clipped at 1 like the value
    EXPECT_NEAR(value(p, CrackleParams{}), std::clamp(d[1] - d[0], 0.0, 1.0), 1e-12);
  }
}

TEST(Crackle, OffsetAddsToEachSquaredDistance) {
  const Vec3 p{1.37, 0.52, -2.2};
  const double d1 = value(p, CrackleParams{{1, 0, 0}, 2, 0, false});
  EXPECT_NEAR(value(p, CrackleParams{{1, 0, 0}, 2, 0.3, false}), std::sqrt(d1 * d1 + 0.09), 1e-12);
}

TEST(Crackle, NearestPointIsWithinTheNeighbourhood) {
  // Every unit cube holds one point, so the nearest is never farther than the cube's diagonal.
  for (int i = 0; i < 200; ++i) {
    const Vec3 p{i * 0.173 - 9.0, i * 0.311 - 20.0, i * 0.057};
    EXPECT_LE(value(p, CrackleParams{{1, 0, 0}, 2, 0, false}), std::sqrt(3.0));
  }
}

TEST(Crackle, SolidIsConstantNearItsCellPointAndInRange) {
  // Points very close together share their nearest cell point (away from cell borders), so the same shade.
  CrackleParams solid;
  solid.solid = true;
  int same = 0;
  for (int i = 0; i < 100; ++i) {
    const Vec3 p{i * 0.731, i * 0.219 - 7.0, i * 0.443};
    const double a = value(p, solid), b = value(p + Vec3{1e-7, 1e-7, 1e-7}, solid);
    EXPECT_GE(a, 0.0);
    EXPECT_LE(a, 1.0);
    if (a == b) ++same;
  }
  EXPECT_GE(same, 98);
}

TEST(Cells, OneValuePerUnitCube) {
  PatternParams cells;
  cells.kind = PatternKind::cells;
  const double v = pattern_value(cells, {2.1, 3.2, -0.5});
  EXPECT_EQ(pattern_value(cells, {2.9, 3.9, -0.1}), v);
  EXPECT_GE(v, 0.0);
  EXPECT_LT(v, 1.0);
  double sum = 0;   // uniform values: the mean over many cubes is near ½
  for (int i = 0; i < 2000; ++i) sum += pattern_value(cells, {i + 0.5, (i * 7) % 13 + 0.5, (i * 3) % 17 + 0.5});
  EXPECT_NEAR(sum / 2000, 0.5, 0.03);
}

}  // namespace
}  // namespace povtrace::render
