// The deterministic two-level sample store of docs/issue19-study.md §9.2 item 3. During a pass (a pretrace pass
// or the final pass) the global level is immutable and shared by every thread without locks; each block files the
// samples it makes in its own private level, visible only to its own lookups. When the pass ends, the blocks'
// levels are appended to the global one in block order (POV-Ray's +HR visibility rule with one tile id per
// block), so the result depends on the image, the block size and the scene, never on the thread count.
//
// A lookup offers the samples whose node covers the query point (octree.hpp): the global level's, then the
// block's, each in its tree walk's order — fixed by the insertion history, which does not depend on threads.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "renderer/radiosity/octree.hpp"

namespace povtrace::render::radiosity {

// Samples of each bounce depth are indexed apart: a query only ever uses samples of its own depth (weights.hpp
// sample_visible), as POV-Ray's octree walk tests the depth first.
template <class Sample>
class SampleLevel {
 public:
  // Files `s`, made at bounce depth `depth`, under `node`; returns its id in this level (the number of samples
  // before it).
  std::uint32_t add(const NodeKey& node, const Sample& s, int depth = 0) {
    const auto id = static_cast<std::uint32_t>(samples_.size());
    samples_.push_back(s);
    nodes_.push_back(node);
    depths_.push_back(depth);
    if (static_cast<std::size_t>(depth) >= index_.size()) index_.resize(static_cast<std::size_t>(depth) + 1);
    index_[static_cast<std::size_t>(depth)].insert(node, id);
    return id;
  }

  // Appends to `ids` the id of every sample of bounce depth `depth` whose node covers p (NodeIndex::covering's
  // order).
  void covering(Vec3 p, std::vector<std::uint32_t>& ids, int depth = 0) const {
    if (static_cast<std::size_t>(depth) < index_.size()) index_[static_cast<std::size_t>(depth)].covering(p, ids);
  }

  const Sample& operator[](std::uint32_t id) const { return samples_[id]; }
  const NodeKey& node(std::uint32_t id) const { return nodes_[id]; }
  std::size_t size() const { return samples_.size(); }
  bool empty() const { return samples_.empty(); }

  // Appends every sample of `other`, in its order, under the node it was filed in.
  void append(const SampleLevel& other) {
    for (std::uint32_t id = 0; id < other.size(); ++id) add(other.nodes_[id], other.samples_[id], other.depths_[id]);
  }

  void clear() {
    samples_.clear();
    nodes_.clear();
    depths_.clear();
    index_.clear();
  }

 private:
  std::vector<Sample> samples_;
  std::vector<NodeKey> nodes_;
  std::vector<int> depths_;
  std::vector<NodeIndex> index_;   // per depth
};

// The pass merge: appends the blocks' levels to `global` in the order given (block serial order), then empties
// them for the next pass. Single-threaded, between passes.
template <class Sample>
void merge_blocks(SampleLevel<Sample>& global, std::span<SampleLevel<Sample>> blocks_in_serial_order) {
  for (SampleLevel<Sample>& block : blocks_in_serial_order) {
    global.append(block);
    block.clear();
  }
}

// Calls visit(sample) for every sample of depth `depth` of `global` then of `block` whose node covers p, each level
// in its walk's order. `scratch` is the caller's reusable buffer (one per thread).
template <class Sample, class Visit>
void for_each_candidate(const SampleLevel<Sample>& global, const SampleLevel<Sample>& block, Vec3 p,
                        std::vector<std::uint32_t>& scratch, Visit&& visit, int depth = 0) {
  for (const SampleLevel<Sample>* level : {&global, &block}) {
    scratch.clear();
    level->covering(p, scratch, depth);
    for (const std::uint32_t id : scratch) visit((*level)[id]);
  }
}

}  // namespace povtrace::render::radiosity
