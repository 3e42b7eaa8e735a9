// A bicubic_patch as the renderer keeps it: POV-Ray 3.7's tree of sub-patches (bicubic_patch.cpp builds and walks
// it), in the scene's own space (the parser has already moved the control points).
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "scene/description.hpp"
#include "renderer/geometry.hpp"

namespace povtrace::render {

struct BicubicPatchData : ShapeData {
  // A node's sub-net is bounded by a sphere (centre, squared radius); an inner node's 2 or 4 children are
  // consecutive from `first`, a leaf's quad is leaves[first].
  struct Node {
    Vec3 centre;
    double radius2 = 0;
    std::uint32_t first = 0;
    std::uint8_t children = 0;   // 0 for a leaf
  };
  // A leaf quad: its sub-net's corners P[0][0], P[0][3], P[3][3], P[3][0] at (u0, v0), (u0, v1), (u1, v1), (u1, v0),
  // and the whole patch's unit normal at each (POV-Ray's bezier_value, evaluated once here rather than per hit).
  struct Leaf {
    std::array<Vec3, 4> corner;
    std::array<Vec3, 4> normal;
    double u0 = 0, u1 = 1, v0 = 0, v1 = 1;
  };
  std::vector<Node> nodes;   // nodes[0] is the whole patch
  std::vector<Leaf> leaves;
  std::array<std::array<double, 2>, 4> uv_vectors{};
  Bounds bounds;
};

std::shared_ptr<BicubicPatchData> bicubic_patch_data(const BicubicPatch& patch, const Matrix& world_from_object);

}  // namespace povtrace::render

namespace povtrace::render::shapes {

// bicubic_patch (bicubic_patch.cpp): BicubicPatchData in world space; every triangle of every leaf the ray meets is
// a hit (element = 2·leaf + triangle, u and v its weights of the triangle's second and third corners). Never
// inside, as in POV-Ray.
struct BicubicPatchShape {
  using Description = BicubicPatch;
  static Primitive build(const BicubicPatch& description, const Matrix& world_from_object);
  static void collect(const Primitive& p, const Ray& ray, HitBuffer& out);
  static std::optional<SurfaceHit> nearest(const Primitive& p, const Ray& ray, double t_min, double t_max);
  static Vec3 hit_normal(const SurfaceHit& hit, Vec3 world_point);
  static Vec3 normal(const Primitive& p, Vec3 world_point);
  static std::array<double, 2> uv(const SurfaceHit& hit, Vec3 world_point);
  static Bounds world_bounds(const Primitive& p);
};

}  // namespace povtrace::render::shapes
