// Build of the per-mesh triangle BVH (triangle_bvh.hpp): top-down binned SAH (16 bins per axis, leaves of at most
// 4 triangles), switching to object-median splits below depth 32 so the depth stays under 64 for any input. Build
// temporaries are single precision: one box per triangle (24 bytes, freed after the build); its centroid is
// recomputed from the box where needed, with the same float operations, rather than kept (12 bytes more per
// triangle, 12 MB at a million triangles, at the peak of a large mesh's memory).
#include "renderer/accel/triangle_bvh.hpp"

#include <algorithm>
#include <array>
#include <limits>

#include "renderer/accel/binned_sah.hpp"

namespace povtrace::render {

namespace {
constexpr std::uint32_t max_leaf_size = 4;
constexpr int sah_depth_limit = 32;

struct Box3f {
  std::array<float, 3> lo{std::numeric_limits<float>::infinity(), std::numeric_limits<float>::infinity(),
                          std::numeric_limits<float>::infinity()};
  std::array<float, 3> hi{-std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity(),
                          -std::numeric_limits<float>::infinity()};
  void extend(const Box3f& b) {
    for (int i = 0; i < 3; ++i) {
      lo[i] = std::min(lo[i], b.lo[i]);
      hi[i] = std::max(hi[i], b.hi[i]);
    }
  }
  void extend(const std::array<float, 3>& p) {
    for (int i = 0; i < 3; ++i) {
      lo[i] = std::min(lo[i], p[i]);
      hi[i] = std::max(hi[i], p[i]);
    }
  }
  double surface_area() const {
    if (lo[0] > hi[0]) return 0.0;
    const double x = double(hi[0]) - lo[0], y = double(hi[1]) - lo[1], z = double(hi[2]) - lo[2];
    return 2.0 * (x * y + y * z + z * x);
  }
};

class Builder {
 public:
  Builder(const std::vector<float>& vertices, const std::vector<std::uint32_t>& faces,
          std::vector<TriangleBvh::Node>& nodes, std::vector<std::uint32_t>& order)
      : nodes_(nodes), order_(order) {
    const std::size_t n = faces.size() / 3;
    boxes_.resize(n);
    order_.resize(n);
    for (std::size_t t = 0; t < n; ++t) {
      Box3f b;
      for (int k = 0; k < 3; ++k) {
        const float* v = &vertices[3 * std::size_t(faces[3 * t + k])];
        b.extend(std::array<float, 3>{v[0], v[1], v[2]});
      }
      boxes_[t] = b;
      order_[t] = static_cast<std::uint32_t>(t);
    }
    // SAH trees of meshes come out with between n/2 and n nodes: reserving n avoids the reallocation from n/2,
    // during which both arrays (48 bytes per triangle) were alive next to the boxes. The surplus is given back
    // by shrink_to_fit once the boxes are freed.
    nodes_.reserve(n + 1);
    if (n > 0) build(0, static_cast<std::uint32_t>(n), 0);
  }

 private:
  std::uint32_t build(std::uint32_t begin, std::uint32_t end, int depth) {
    const auto index = static_cast<std::uint32_t>(nodes_.size());
    nodes_.emplace_back();
    Box3f box, centroid_box;
    for (std::uint32_t k = begin; k < end; ++k) {
      box.extend(boxes_[order_[k]]);
      centroid_box.extend(centroid(order_[k]));
    }
    for (int i = 0; i < 3; ++i) {
      nodes_[index].lo[i] = box.lo[i];
      nodes_[index].hi[i] = box.hi[i];
    }
    const std::uint32_t count = end - begin;
    if (count <= max_leaf_size) {
      nodes_[index].first = begin;
      nodes_[index].count = static_cast<std::uint16_t>(count);
      return index;
    }
    int axis = 0;
    for (int a = 1; a < 3; ++a)
      if (centroid_box.hi[a] - centroid_box.lo[a] > centroid_box.hi[axis] - centroid_box.lo[axis]) axis = a;
    std::uint32_t mid = 0;
    if (!(depth < sah_depth_limit && sah_split(begin, end, centroid_box, axis, mid))) {
      mid = begin + count / 2;
      std::nth_element(order_.begin() + begin, order_.begin() + mid, order_.begin() + end,
                       [&](std::uint32_t l, std::uint32_t r) { return centroid(l, axis) < centroid(r, axis); });
    }
    nodes_[index].axis = static_cast<std::uint16_t>(axis);
    build(begin, mid, depth + 1);   // the left child lands at index + 1
    const std::uint32_t right = build(mid, end, depth + 1);
    nodes_[index].first = right;
    return index;
  }

  float centroid(std::uint32_t t, int axis) const { return 0.5f * (boxes_[t].lo[axis] + boxes_[t].hi[axis]); }
  std::array<float, 3> centroid(std::uint32_t t) const { return {centroid(t, 0), centroid(t, 1), centroid(t, 2)}; }

  // The bin of a triangle's centroid on `axis`, as a callable made once per axis (binned_sah.hpp). `Axis`: int, or a
  // std::integral_constant in the SAH sweep, which makes the coordinate's offset a constant.
  template <class Axis>
  auto binner_for(Axis axis, const Box3f& centroid_box) const {
    const double lo = centroid_box.lo[axis];
    const double scale = sah_bin_count / (double(centroid_box.hi[axis]) - centroid_box.lo[axis]);
    return [boxes = boxes_.data(), axis, lo, scale](std::uint32_t t) {
      const float c = 0.5f * (boxes[t].lo[axis] + boxes[t].hi[axis]);   // centroid(t, axis)
      return std::clamp(static_cast<int>((double(c) - lo) * scale), 0, sah_bin_count - 1);
    };
  }

  // The cheapest binned SAH split over the three axes; partitions order_ and sets mid/axis. False when no split
  // separates the triangles.
  bool sah_split(std::uint32_t begin, std::uint32_t end, const Box3f& centroid_box, int& axis, std::uint32_t& mid) {
    const auto bin = [&](auto a) { return binner_for(a, centroid_box); };
    const SahSplit split = cheapest_sah_split<Box3f>(
        order_.data() + begin, order_.data() + end,
        [&](int a) { return centroid_box.hi[a] > centroid_box.lo[a]; }, bin,
        [&](std::uint32_t t) -> const Box3f& { return boxes_[t]; });
    if (split.axis < 0) return false;
    mid = static_cast<std::uint32_t>(partition_at(order_.data() + begin, order_.data() + end, split, bin) -
                                     order_.data());
    axis = split.axis;
    return mid > begin && mid < end;
  }

  std::vector<TriangleBvh::Node>& nodes_;
  std::vector<std::uint32_t>& order_;
  std::vector<Box3f> boxes_;
};
}  // namespace

TriangleBvh::TriangleBvh(const std::vector<float>& vertices, const std::vector<std::uint32_t>& faces) {
  Builder(vertices, faces, nodes_, order_);
  nodes_.shrink_to_fit();
}

Bounds TriangleBvh::bounds() const {
  if (nodes_.empty()) return {};
  const Node& root = nodes_[0];
  return Bounds{{root.lo[0], root.lo[1], root.lo[2]}, {root.hi[0], root.hi[1], root.hi[2]}};
}

}  // namespace povtrace::render
