// The two-level sample store: a block's lookups see the global samples then its own, in the order the pass merge
// will give them, and the merge appends the blocks in serial order whatever order they finished in
// (docs/issue19-study.md §9.2 item 3).
#include <gtest/gtest.h>

#include <algorithm>

#include <cstdint>
#include <random>
#include <vector>

#include "renderer/radiosity/sample_levels.hpp"

namespace povtrace::render::radiosity {
namespace {

struct Tagged {
  Vec3 point;
  int block = 0;
  int seq = 0;
  friend bool operator==(const Tagged&, const Tagged&) = default;
};

std::vector<Tagged> candidates(const SampleLevel<Tagged>& global, const SampleLevel<Tagged>& block, Vec3 p) {
  std::vector<std::uint32_t> scratch;
  std::vector<Tagged> seen;
  for_each_candidate(global, block, p, scratch, [&](const Tagged& t) { seen.push_back(t); });
  return seen;
}

std::vector<Tagged> candidates(const SampleLevel<Tagged>& level, Vec3 p) {
  std::vector<std::uint32_t> ids;
  level.covering(p, ids);
  std::vector<Tagged> seen;
  for (const std::uint32_t id : ids) seen.push_back(level[id]);
  return seen;
}

TEST(SampleLevels, BlockSeesGlobalThenItsOwnInMergedOrder) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> coord(-2, 2), radius(0.01, 0.8);
  SampleLevel<Tagged> global;
  for (int seq = 0; seq < 200; ++seq) {
    const Vec3 p{coord(rng), coord(rng), coord(rng)};
    global.add(filing_node(p, radius(rng)), {p, -1, seq});
  }
  std::vector<SampleLevel<Tagged>> blocks(4);
  // Blocks fill their levels in any order (as threads would); each block's own samples in its own order.
  for (const int b : {2, 0, 3, 1})
    for (int seq = 0; seq < 50; ++seq) {
      const Vec3 p{coord(rng), coord(rng), coord(rng)};
      blocks[static_cast<std::size_t>(b)].add(filing_node(p, radius(rng)), {p, b, seq});
    }
  // What block 2 saw during the pass, per query point.
  std::vector<Vec3> queries;
  std::vector<std::vector<Tagged>> during;
  for (int i = 0; i < 300; ++i) {
    queries.push_back({coord(rng), coord(rng), coord(rng)});
    during.push_back(candidates(global, blocks[2], queries.back()));
  }
  const SampleLevel<Tagged> block2 = blocks[2];
  merge_blocks(global, std::span<SampleLevel<Tagged>>(blocks));
  ASSERT_EQ(global.size(), 400u);
  for (const SampleLevel<Tagged>& b : blocks) EXPECT_TRUE(b.empty());
  // Serial order: block 0's samples, then 1, 2, 3, each in creation order.
  for (std::uint32_t id = 200; id < 400; ++id) {
    EXPECT_EQ(global[id].block, static_cast<int>((id - 200) / 50));
    EXPECT_EQ(global[id].seq, static_cast<int>((id - 200) % 50));
  }
  // After the merge the same query, restricted to the global samples and block 2's, offers the same samples.
  auto by_origin = [](std::vector<Tagged> v) {
    std::sort(v.begin(), v.end(), [](const Tagged& a, const Tagged& b) {
      return std::pair(a.block, a.seq) < std::pair(b.block, b.seq);
    });
    return v;
  };
  std::size_t total = 0;
  for (std::size_t i = 0; i < queries.size(); ++i) {
    std::vector<Tagged> after;
    for (const Tagged& t : candidates(global, queries[i]))
      if (t.block == -1 || t.block == 2) after.push_back(t);
    ASSERT_EQ(by_origin(after), by_origin(during[i])) << "query " << i;
    total += after.size();
  }
  EXPECT_GT(total, 300u);
  // The merged level files every sample under the node it had in its block.
  for (std::uint32_t id = 0; id < block2.size(); ++id) EXPECT_EQ(global.node(300 + id), block2.node(id));
}

}  // namespace
}  // namespace povtrace::render::radiosity
