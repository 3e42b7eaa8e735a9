// POV-Ray's sample jitter (runtime/jitter.hpp): the table made by its rule, spot-checked against values POV-Ray 3.7's
// table holds, and Jitter2d's two-level lookup through the lattice permutation.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "runtime/jitter.hpp"

namespace {

using namespace povtrace;

TEST(JitterTable, SpotValuesOfPovRaysTable) {
  // Written in POV-Ray's jitter.cpp with six decimals: the first entries, and entries whose exact value is a
  // half in the sixth decimal (rounded away from zero there: −0.3828125 is written −0.382813).
  EXPECT_EQ(jitter_table_entry(0), -0.5f);
  EXPECT_EQ(jitter_table_entry(1), 0.005890f);
  EXPECT_EQ(jitter_table_entry(2), 0.011749f);
  EXPECT_EQ(jitter_table_entry(3), -0.490234f);
  EXPECT_EQ(jitter_table_entry(20), -0.382813f);
  EXPECT_EQ(jitter_table_entry(156), 0.320313f);
  EXPECT_EQ(jitter_table_entry(252), 0.007813f);
}

TEST(JitterTable, EveryEntryDistinctWithinHalfAndBalanced) {
  std::set<float> seen;
  double sum = 0;
  for (int i = 0; i < 256; ++i) {
    const float v = jitter_table_entry(i);
    EXPECT_GE(v, -0.5f);
    EXPECT_LT(v, 0.5f);
    seen.insert(v);
    sum += v;
  }
  EXPECT_EQ(seen.size(), 256u);
  EXPECT_NEAR(sum / 256, 0.0, 2e-3);
  EXPECT_EQ(jitter_table_entry(256), jitter_table_entry(0));   // the index wraps at 8 bits as POV-Ray masks it
}

TEST(Jitter2d, TwoLevelLookupWithSwappedPrimes) {
  for (const auto& [x, y] : {std::pair{0.0, 0.0}, std::pair{12.25, 7.75}, std::pair{-1.3, 5.5}, std::pair{319.9, 239.4}}) {
    const auto [jx, jy] = povray_jitter2d(x, y);
    const int ax = static_cast<int>(x * 1021.0), bx = static_cast<int>(y * 1019.0);
    const int ay = static_cast<int>(x * 1019.0), by = static_cast<int>(y * 1021.0);
    const double want_x = jitter_table_entry(lattice_permutation_entry((lattice_permutation_entry(ax & 0xfff) ^ bx) & 0xfff) & 0xff);
    const double want_y = jitter_table_entry(lattice_permutation_entry((lattice_permutation_entry(ay & 0xfff) ^ by) & 0xfff) & 0xff);
    EXPECT_EQ(jx, want_x) << x << "," << y;
    EXPECT_EQ(jy, want_y) << x << "," << y;
  }
  // Truncation towards zero, as POV-Ray's int(): −0.0005 · 1021 = −0.51 becomes 0, the same cell as the origin.
  EXPECT_EQ(povray_jitter2d(-0.0005, 0.0), povray_jitter2d(0.0, 0.0));
}

}  // namespace
