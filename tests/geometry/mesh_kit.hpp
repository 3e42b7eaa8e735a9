// Triangle-based primitives built in code for the geometry tests: single triangles, meshes from arrays, an
// icosphere (a closed mesh whose shared edges and vertices the watertightness tests aim at).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <memory>
#include <vector>

#include "renderer/shapes/triangle_shapes.hpp"
#include "tests/geometry/geometry_kit.hpp"

namespace povtrace::test {

inline render::Primitive triangle(Vec3 a, Vec3 b, Vec3 c, const Matrix& world_from_object = Matrix::identity()) {
  render::Primitive p;
  p.type = render::ShapeType::triangle;
  p.world_from_object = world_from_object;
  render::shapes::set_up_triangle(p, Triangle{{a, b, c}, std::nullopt, false});
  return p;
}

inline std::shared_ptr<const MeshData> mesh_data(const std::vector<Vec3>& vertices,
                                                 const std::vector<std::uint32_t>& faces) {
  auto d = std::make_shared<MeshData>();
  for (const Vec3& v : vertices)
    d->vertices.insert(d->vertices.end(), {float(v.x), float(v.y), float(v.z)});
  d->faces = faces;
  return d;
}

inline render::Primitive mesh(std::shared_ptr<const MeshData> data) {
  render::Primitive p;
  p.type = render::ShapeType::mesh;
  render::shapes::set_up_mesh(p, render::shapes::make_mesh_shape(data));
  return p;
}

// An icosahedron subdivided `levels` times, vertices on the unit sphere (single-precision values).
inline std::shared_ptr<const MeshData> icosphere(int levels) {
  const double g = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<Vec3> v = {{-1, g, 0}, {1, g, 0}, {-1, -g, 0}, {1, -g, 0}, {0, -1, g}, {0, 1, g},
                         {0, -1, -g}, {0, 1, -g}, {g, 0, -1}, {g, 0, 1}, {-g, 0, -1}, {-g, 0, 1}};
  std::vector<std::uint32_t> f = {0, 11, 5, 0, 5, 1, 0, 1, 7, 0, 7, 10, 0, 10, 11, 1, 5, 9, 5, 11, 4,
                                  11, 10, 2, 10, 7, 6, 7, 1, 8, 3, 9, 4, 3, 4, 2, 3, 2, 6, 3, 6, 8,
                                  3, 8, 9, 4, 9, 5, 2, 4, 11, 6, 2, 10, 8, 6, 7, 9, 8, 1};
  for (Vec3& p : v) p = normalize(p);
  for (int level = 0; level < levels; ++level) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> midpoint;
    auto mid = [&](std::uint32_t a, std::uint32_t b) {
      const auto key = std::minmax(a, b);
      if (auto it = midpoint.find(key); it != midpoint.end()) return it->second;
      v.push_back(normalize((v[a] + v[b]) * 0.5));
      return midpoint[key] = static_cast<std::uint32_t>(v.size() - 1);
    };
    std::vector<std::uint32_t> next;
    for (std::size_t i = 0; i < f.size(); i += 3) {
      const std::uint32_t a = f[i], b = f[i + 1], c = f[i + 2];
      const std::uint32_t ab = mid(a, b), bc = mid(b, c), ca = mid(c, a);
      next.insert(next.end(), {a, ab, ca, b, bc, ab, c, ca, bc, ab, bc, ca});
    }
    f = std::move(next);
  }
  return mesh_data(v, f);
}

}  // namespace povtrace::test
