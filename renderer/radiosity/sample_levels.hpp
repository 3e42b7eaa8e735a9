// The deterministic two-level sample store of docs/issue19-study.md §9.2 item 3. During a pass (a pretrace pass
// or the final pass) the global level is immutable and shared by every thread without locks; each block files the
// samples it makes in its own private level, visible only to its own lookups. When the pass ends, the blocks'
// levels are appended to the global one in block order (POV-Ray's +HR visibility rule with one tile id per
// block), so the result depends on the image, the block size and the scene, never on the thread count.
//
// A lookup offers the samples whose node covers the query point (octree.hpp): the global level's in insertion
// order, then the block's in insertion order, which is the order they will have after the merge.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "renderer/radiosity/octree.hpp"

namespace povtrace::render::radiosity {

template <class Sample>
class SampleLevel {
 public:
  // Files `s` under `node`; returns its id in this level (the number of samples before it).
  std::uint32_t add(const NodeKey& node, const Sample& s) {
    const auto id = static_cast<std::uint32_t>(samples_.size());
    samples_.push_back(s);
    nodes_.push_back(node);
    index_.insert(node, id);
    return id;
  }

  // Appends to `ids`, increasing, the id of every sample whose node covers p.
  void covering(Vec3 p, std::vector<std::uint32_t>& ids) const { index_.covering(p, ids); }

  const Sample& operator[](std::uint32_t id) const { return samples_[id]; }
  const NodeKey& node(std::uint32_t id) const { return nodes_[id]; }
  std::size_t size() const { return samples_.size(); }
  bool empty() const { return samples_.empty(); }

  // Appends every sample of `other`, in its order, under the node it was filed in.
  void append(const SampleLevel& other) {
    for (std::uint32_t id = 0; id < other.size(); ++id) add(other.nodes_[id], other.samples_[id]);
  }

  void clear() {
    samples_.clear();
    nodes_.clear();
    index_.clear();
  }

 private:
  std::vector<Sample> samples_;
  std::vector<NodeKey> nodes_;
  NodeIndex index_;
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

// Calls visit(sample) for every sample of `global` then of `block` whose node covers p, each level in insertion
// order. `scratch` is the caller's reusable buffer (one per thread).
template <class Sample, class Visit>
void for_each_candidate(const SampleLevel<Sample>& global, const SampleLevel<Sample>& block, Vec3 p,
                        std::vector<std::uint32_t>& scratch, Visit&& visit) {
  for (const SampleLevel<Sample>* level : {&global, &block}) {
    scratch.clear();
    level->covering(p, scratch);
    for (const std::uint32_t id : scratch) visit((*level)[id]);
  }
}

}  // namespace povtrace::render::radiosity
