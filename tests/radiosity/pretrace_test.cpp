// The pretrace's geometry (renderer/radiosity/pretrace.*): pass count and cell sizes (docs/issue19-study.md §2.1
// table), POV-Ray's jitter cycle (mt19937 outputs, values computed here by an independent Python implementation of
// the Mersenne Twister), the points of a block, the stop rule and the adaptive split (§2.4).
#include <gtest/gtest.h>

#include "renderer/radiosity/pretrace.hpp"

namespace {

using namespace povtrace::render::radiosity;

TEST(PretraceCellSizes, MatchPovRaysPassTable) {
  EXPECT_EQ(pretrace_cell_sizes(160, 120, 0.08, 0.04), (std::vector<double>{12.8, 6.4}));
  EXPECT_EQ(pretrace_cell_sizes(800, 600, 0.08, 0.04), (std::vector<double>{64, 32}));
  const std::vector<double> big = pretrace_cell_sizes(1024, 768, 0.08, 0.04);
  ASSERT_EQ(big.size(), 2u);
  EXPECT_DOUBLE_EQ(big[0], 81.92);
  EXPECT_DOUBLE_EQ(big[1], 40.96);
  EXPECT_EQ(pretrace_cell_sizes(800, 600, 0.16, 0.01), (std::vector<double>{128, 64, 32, 16, 8}));
  EXPECT_EQ(pretrace_cell_sizes(800, 600, 0.05, 0.05), (std::vector<double>{40}));
  // The end is at least one pixel: 0.004·160 = 0.64 → 1, so 12.8 … 1.6 then 1.
  EXPECT_EQ(pretrace_cell_sizes(160, 120, 0.08, 0.004), (std::vector<double>{12.8, 6.4, 3.2, 1.6, 1}));
  // A first cell under one pixel: no pretrace at all (a 1×1 image with the defaults).
  EXPECT_TRUE(pretrace_cell_sizes(1, 1, 0.08, 0.04).empty());
}

TEST(PretraceJitter, IsTheMersenneTwisterCycleReadAfterTheSeed) {
  const auto& t = PretraceJitter::table();
  EXPECT_DOUBLE_EQ(t[0], 0.6294473838061094);    // 3499211612 / 2^32 · 2 − 1
  EXPECT_DOUBLE_EQ(t[2046], 0.2802330916747451);
  PretraceJitter j;
  j.seed(1, 0);                                   // index 17: the first read is entry 18
  EXPECT_DOUBLE_EQ(j.next(), 0.9297770676203072);
  EXPECT_DOUBLE_EQ(j.next(), 0.9353898735716939);
  j.seed(2, 155);                                 // 2·17 + 155·13 = 2049 → 2: wraps modulo 2047
  EXPECT_DOUBLE_EQ(j.next(), t[3]);
  j.seed(0, 0);
  for (int i = 0; i < PretraceJitter::size - 1; ++i) (void)j.next();
  EXPECT_DOUBLE_EQ(j.next(), t[0]);               // after 2047 reads the cycle starts again
}

TEST(PretracePoints, AGlobalGridJitteredAroundEachCellCentre) {
  PretraceJitter j;
  const PretraceBlockState fresh;
  j.seed(1, 0);
  const std::vector<PretracePoint> first = pretrace_points({0, 0, 31, 31}, fresh, {}, 12.8, j);
  ASSERT_EQ(first.size(), 9u);   // grid 0, 12.8, 25.6 on both axes
  PretraceJitter k;
  k.seed(1, 0);
  const double jy = k.next(), jx = k.next();   // y drawn first (GCC's right-to-left arguments in POV-Ray)
  EXPECT_DOUBLE_EQ(first[0].x, 5.9 + jx);
  EXPECT_DOUBLE_EQ(first[0].y, 5.9 + jy);
  EXPECT_NEAR(first[1].x, 12.8 + 5.9, 1.0);
  EXPECT_NEAR(first[3].y, 12.8 + 5.9, 1.0);
  // The next block's grid starts at the first multiple of 12.8 at or after 31.5: 38.4, 51.2.
  const std::vector<PretracePoint> second = pretrace_points({32, 0, 63, 31}, fresh, {}, 12.8, j);
  ASSERT_EQ(second.size(), 6u);
  EXPECT_NEAR(second[0].x, 38.4 + 5.9, 1.0);
  EXPECT_NEAR(second[1].x, 51.2 + 5.9, 1.0);
  // A one-pixel cell: no offset, jitter at most ½ pixel.
  const std::vector<PretracePoint> fine = pretrace_points({0, 0, 3, 3}, fresh, {}, 1, j);
  ASSERT_EQ(fine.size(), 16u);
  for (std::size_t i = 0; i < fine.size(); ++i) {
    EXPECT_LE(std::abs(fine[i].x - static_cast<double>(i % 4)), 0.5);
    EXPECT_LE(std::abs(fine[i].y - static_cast<double>(i / 4)), 0.5);
  }
}

TEST(PretracePoints, ASubBlockTakesTheGridPointsInsideItsBounds) {
  PretraceJitter j;
  PretraceBlockState halves;
  halves.sub_count_x = 2;
  halves.sub_count_y = 1;
  // Block 0…31, cells of 4: grid 0, 4, …, 28; the right half [16, 32) holds 16, 20, 24, 28.
  const std::vector<PretracePoint> right = pretrace_points({0, 0, 31, 31}, halves, {1, 0}, 4, j);
  ASSERT_EQ(right.size(), 32u);
  for (const PretracePoint& p : right) EXPECT_GE(p.x, 16 + 1.5 - 1.0);
}

TEST(PretraceStopRule, AsRadiosityTaskJudgesABlock) {
  EXPECT_TRUE(pretrace_again(8, 0, 0, 0));      // fewer than 9 points: always another pass
  EXPECT_FALSE(pretrace_again(9, 0, 0, 0));     // nothing asked for radiosity: done
  EXPECT_TRUE(pretrace_again(9, 10, 100, 0));   // no adaptive coverage: every pass
  EXPECT_FALSE(pretrace_again(9, 10, 40, 3));   // average 4·Σw 4 ≥ 3: done
  EXPECT_TRUE(pretrace_again(9, 10, 20, 3));    // 2 < 3: again
}

TEST(PretraceSplit, KeepsFourNextPassPointsAcrossEachSubBlock) {
  EXPECT_EQ(pretrace_split(32, 3.2, 1, 0), 1);   // not adaptive: never split
  EXPECT_EQ(pretrace_split(32, 3.2, 1, 3), 2);   // ⌊(32 + 2.2)/3.2⌋ = 10 points → ⌊10/4⌋ = 2
  EXPECT_EQ(pretrace_split(32, 3.2, 2, 3), 1);   // ⌊10/8⌋ = 1
  EXPECT_EQ(pretrace_split(32, 1, 2, 3), 4);     // 32 points → ⌊32/8⌋ = 4
  EXPECT_EQ(pretrace_split(32, 12.8, 1, 3), 1);  // 3 points: max(1, 0)
}

}  // namespace
