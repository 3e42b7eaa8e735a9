// The binned surface-area-heuristic split shared by the scene BVH (bvh.cpp) and the per-mesh triangle BVH
// (triangle_bvh.cpp): the items of a node are sorted into 16 centroid bins on each usable axis, and the SAH cost
// A_left·N_left + A_right·N_right is evaluated at the 15 bin boundaries by one sweep from the right (areas and counts
// of the right sides) and one from the left; the cheapest boundary over the three axes wins, the first one on a tie.
// The two BVHs differ only in their box type (double or single precision) and how they bin an item, which the
// caller passes in.
#pragma once

#include <algorithm>
#include <cstdint>
#include <limits>
#include <type_traits>

namespace povtrace::render {

inline constexpr int sah_bin_count = 16;

// Where a node splits: items in bins 0 … last_left_bin of `axis` go left. axis < 0: no split separates them.
struct SahSplit {
  int axis = -1;
  int last_left_bin = -1;
};

// The cheapest split of the items [first, last). `usable(a)`: whether axis a has a non-degenerate centroid extent;
// `binner_for(a)`: a callable giving an item's bin on axis a (an int, or a std::integral_constant in the sweep), in
// [0, sah_bin_count) — made once per axis, so that
// the axis's offset and scale are plain values in the binning loop (a lambda reading them through references
// cost the scene BVH build 30% more instructions); `box_of(item)`: its box. Box is default-constructed empty and has
// extend(const Box&) and surface_area().
template <class Box, class Usable, class BinnerFor, class BoxOf>
SahSplit cheapest_sah_split(const std::uint32_t* first, const std::uint32_t* last, Usable usable,
                            BinnerFor binner_for, BoxOf box_of) {
  double best_cost = std::numeric_limits<double>::infinity();
  SahSplit best;
  // The axis is a compile-time constant in each of the three passes (std::integral_constant, which converts to int
  // where a caller takes one), so that a binner may read the axis's coordinate at a fixed offset.
  const auto consider_axis = [&](auto axis) {
    const int a = axis;
    if (!usable(a)) return;
    Box bins[sah_bin_count];
    std::uint32_t counts[sah_bin_count] = {};
    const auto bin_of = binner_for(axis);
    for (const std::uint32_t* k = first; k != last; ++k) {
      const int b = bin_of(*k);
      ++counts[b];
      bins[b].extend(box_of(*k));
    }
    // Sweep from the right, then from the left, evaluating the cost of splitting after bin s.
    double right_area[sah_bin_count];
    std::uint32_t right_count[sah_bin_count];
    Box acc;
    std::uint32_t acc_count = 0;
    for (int s = sah_bin_count - 1; s > 0; --s) {
      acc.extend(bins[s]);
      acc_count += counts[s];
      right_area[s] = acc.surface_area();
      right_count[s] = acc_count;
    }
    acc = Box{};
    acc_count = 0;
    for (int s = 0; s < sah_bin_count - 1; ++s) {
      acc.extend(bins[s]);
      acc_count += counts[s];
      if (acc_count == 0 || right_count[s + 1] == 0) continue;
      const double cost = acc.surface_area() * acc_count + right_area[s + 1] * right_count[s + 1];
      if (cost < best_cost) {
        best_cost = cost;
        best = SahSplit{a, s};
      }
    }
  };
  consider_axis(std::integral_constant<int, 0>{});
  consider_axis(std::integral_constant<int, 1>{});
  consider_axis(std::integral_constant<int, 2>{});
  return best;
}

// Moves the items left of `split` before the others; returns where the right side begins.
template <class BinnerFor>
std::uint32_t* partition_at(std::uint32_t* first, std::uint32_t* last, SahSplit split, BinnerFor binner_for) {
  const auto bin_of = binner_for(split.axis);
  return std::partition(first, last, [&](std::uint32_t item) { return bin_of(item) <= split.last_left_bin; });
}

}  // namespace povtrace::render
