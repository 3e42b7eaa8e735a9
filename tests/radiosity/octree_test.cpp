// Node choice, coverage and the lookup of the radiosity sample index (docs/issue19-study.md §3.5).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "renderer/radiosity/octree.hpp"

namespace povtrace::render::radiosity {
namespace {

TEST(OctreeNode, SizeCodesAreSingleFloatExponents) {
  EXPECT_EQ(node_side(127), 1.0);
  EXPECT_EQ(node_side(126), 0.5);
  EXPECT_EQ(node_side(130), 8.0);
  EXPECT_EQ(node_side(121), 1.0 / 64);
}

TEST(OctreeNode, StudyExample) {
  // Radius 0.3 at (0.1, 0.2, 0.3): box width 0.6 → side 0.5 (code 126); positions ⌊(c + 1e7)/0.5⌋ = 2·10⁷;
  // the cell [0, 0.5) expanded to [−0.25, 0.75) holds the box [c − 0.3, c + 0.3] on every axis: no parent step.
  const NodeKey n = filing_node({0.1, 0.2, 0.3}, 0.3);
  EXPECT_EQ(n, (NodeKey{126, 20000000, 20000000, 20000000}));
  EXPECT_TRUE(node_covers(n, {-0.2499, -0.2499, -0.2499}));
  EXPECT_TRUE(node_covers(n, {0.7499, 0.7499, 0.7499}));
  EXPECT_FALSE(node_covers(n, {-0.2501, 0, 0}));
  EXPECT_FALSE(node_covers(n, {0, 0.7501, 0}));
  EXPECT_FALSE(node_covers(n, {0, 0, -0.25}));   // the bound itself is outside (strict test)
  EXPECT_FALSE(node_covers(n, {0.75, 0, 0}));
}

TEST(OctreeNode, OffCentreBoxClimbsToTheParent) {
  // Centre x = 0.49: the side-½ cell [0, 0.5) expanded reaches 0.75 < 0.79 = the box's high x, so the node is
  // its parent: side 1 at position 10⁷ (cell [0, 1) expanded to [−0.5, 1.5)).
  EXPECT_EQ(filing_node({0.49, 0.1, 0.1}, 0.3), (NodeKey{127, 10000000, 10000000, 10000000}));
}

TEST(OctreeNode, WidthIsRoundedToSinglePrecisionBeforeTheFloor) {
  // A width just below 1 that rounds to 1.0f gives side 1, not ½.
  EXPECT_EQ(filing_node({0.25, 0.25, 0.25}, 0.5 - 1e-12).size_code, 127);
  EXPECT_EQ(filing_node({0.25, 0.25, 0.25}, 0.4999).size_code, 126);
}

TEST(OctreeNode, SmallNodesAreDoubledToKeepPositionsBelow1e9) {
  // Radius 0.001 at the origin: width 0.002 → side 2^−9, but (0.001 + 1e7)/2^−9 > 1e9; doubled to 2^−6.
  const NodeKey n = filing_node({0, 0, 0}, 0.001);
  EXPECT_EQ(n.size_code, 127 - 6);
  EXPECT_EQ(n.x, 640000000);
  // So no node near the origin is smaller than 2^−6 (1e7/1e9 = 0.01): a 0.008-wide box (floor 2^−7) gets 2^−6,
  // and at x = 2·10⁷, where (2·10⁷ + 1e7)/2^−6 > 1e9, it gets 2^−5.
  EXPECT_EQ(filing_node({0, 0, 0}, 0.004).size_code, 127 - 6);
  EXPECT_EQ(filing_node({2e7, 0, 0}, 0.004).size_code, 127 - 5);
  // (A 0.6-wide box centred on the origin, a corner of the side-½ grid, climbs to side 1.)
  EXPECT_EQ(filing_node({0, 0, 0}, 0.3).size_code, 127);
  // Zero radius: the side 0 becomes 1 (then no doubling is needed).
  EXPECT_EQ(filing_node({0.2, 0.2, 0.2}, 0).size_code, 127);
}

TEST(OctreeNode, Parents) {
  EXPECT_EQ(parent_node({126, 5, 4, 3}), (NodeKey{127, 2, 2, 1}));
  // Negative positions (only below −1e7): (i + 1)/2 truncated, so −1 and −2 both go to 0, −3 to −1.
  EXPECT_EQ(parent_node({126, -1, -2, -3}), (NodeKey{127, 0, 0, -1}));
}

TEST(OctreeNode, FilingNodeCoversTheBoxAndIsMinimal) {
  std::mt19937 rng(19);
  std::uniform_real_distribution<double> coord(-20, 20), log_radius(-8, 3);
  for (int i = 0; i < 5000; ++i) {
    const Vec3 c{coord(rng), coord(rng), coord(rng)};
    const double r = std::exp(log_radius(rng));
    const NodeKey n = filing_node(c, r);
    const Vec3 lo{c.x - r, c.y - r, c.z - r}, hi{c.x + r, c.y + r, c.z + r};
    ASSERT_TRUE(node_covers(n, lo) && node_covers(n, hi) && node_covers(n, c));
    // The side is at least the largest power of two not above the width, and at most twice the width unless
    // the 1e9 limit applies.
    const double side = node_side(n.size_code);
    ASSERT_GE(side * 2, 2 * r * (1 - 1e-6));
    if (side > 4 * r) {   // only the 1e9 limit makes a node more than twice the box's width
      const double farthest = std::max({std::fabs(lo.x), std::fabs(lo.y), std::fabs(lo.z)}) + 1e7;
      ASSERT_GT(farthest / (side / 4), 1e9 * (1 - 1e-9));
    }
  }
}

TEST(OctreeNode, FilingFactor) {
  EXPECT_EQ(filing_factor(1.8, 0), 1.8);
  EXPECT_EQ(filing_factor(1.8, 1), 1.8 * 2 / 8);
  EXPECT_EQ(filing_factor(1.8, 3), 1.8 * 8 / 8);
}

TEST(NodeIndex, CoveringNodesInInsertionOrder) {
  NodeIndex index;
  const NodeKey a{126, 20000000, 20000000, 20000000};   // [0, 0.5)³ expanded to [−0.25, 0.75)³
  const NodeKey b{127, 10000000, 10000000, 10000000};   // [0, 1)³ expanded to [−0.5, 1.5)³
  const NodeKey c{126, 20000002, 20000000, 20000000};   // x in [1, 1.5) expanded to [0.75, 1.75)
  index.insert(b, 0);
  index.insert(a, 1);
  index.insert(c, 2);
  index.insert(a, 3);
  index.insert(b, 4);
  std::vector<std::uint32_t> ids;
  index.covering({0.1, 0.1, 0.1}, ids);
  EXPECT_EQ(ids, (std::vector<std::uint32_t>{0, 4, 1, 3}));   // the walk: b's samples, then its child a's
  ids.assign({99});   // appends after what the caller holds
  index.covering({1.2, 0.1, 0.1}, ids);
  EXPECT_EQ(ids, (std::vector<std::uint32_t>{99, 0, 4, 2}));
  ids.clear();
  index.covering({1.6, 0.1, 0.1}, ids);
  EXPECT_EQ(ids, (std::vector<std::uint32_t>{2}));
  ids.clear();
  index.covering({5, 5, 5}, ids);
  EXPECT_TRUE(ids.empty());
  EXPECT_EQ(index.size(), 5u);
}

// The index returns exactly the samples whose node covers the point, each once, for samples of every size near
// and far from each other and query points on and off the samples.
TEST(NodeIndex, MatchesBruteForce) {
  std::mt19937 rng(1919);
  std::uniform_real_distribution<double> coord(-5, 5), log_radius(-7, 1.5), jitter(-0.3, 0.3);
  std::vector<NodeKey> nodes;
  std::vector<Vec3> points;
  NodeIndex index;
  for (std::uint32_t id = 0; id < 3000; ++id) {
    const Vec3 p{coord(rng), coord(rng), coord(rng)};
    nodes.push_back(filing_node(p, std::exp(log_radius(rng))));
    points.push_back(p);
    index.insert(nodes.back(), id);
  }
  std::vector<std::uint32_t> got, want;
  std::size_t total = 0;
  for (int i = 0; i < 3000; ++i) {
    const Vec3& centre = points[static_cast<std::size_t>(i)];
    const Vec3 p = i % 2 ? Vec3{coord(rng), coord(rng), coord(rng)}
                         : centre + Vec3{jitter(rng), jitter(rng), jitter(rng)} * (i % 4 ? 1.0 : 0.01);
    got.clear();
    want.clear();
    index.covering(p, got);
    std::sort(got.begin(), got.end());
    for (std::uint32_t id = 0; id < nodes.size(); ++id)
      if (node_covers(nodes[id], p)) want.push_back(id);
    ASSERT_EQ(got, want) << "query " << i;
    total += want.size();
  }
  EXPECT_GT(total, 3000u * 20);   // the comparison is not vacuous: queries see many samples
}

// Points exactly on cell bounds: coverage is strict and the index agrees with the test.
TEST(NodeIndex, BoundaryPointsMatchBruteForce) {
  NodeIndex index;
  std::vector<NodeKey> nodes;
  std::uint32_t id = 0;
  for (int code = 124; code <= 128; ++code)
    for (int dx = -3; dx <= 3; ++dx) {
      const double side = node_side(code);
      const NodeKey n{code, static_cast<int>(1e7 / side) + dx, static_cast<int>(1e7 / side), static_cast<int>(1e7 / side)};
      nodes.push_back(n);
      index.insert(n, id++);
    }
  for (int k = -16; k <= 16; ++k) {
    const Vec3 p{k * 0.125, 0.0625, 0};
    std::vector<std::uint32_t> got, want;
    index.covering(p, got);
    std::sort(got.begin(), got.end());
    for (std::uint32_t i = 0; i < nodes.size(); ++i)
      if (node_covers(nodes[i], p)) want.push_back(i);
    ASSERT_EQ(got, want) << "x = " << p.x;
  }
}

}  // namespace
}  // namespace povtrace::render::radiosity
