// Render-ready data of polynomial surfaces (poly.cpp, quadric.cpp), and their construction from the scene description.
#pragma once

#include <vector>

#include "scene/description.hpp"
#include "renderer/geometry.hpp"

namespace povtrace::render {

struct PolyData : ShapeData {
  static constexpr int max_order = 35;  // POV-Ray's MAX_ORDER, the parser's limit
  int order = 4;
  bool sturm = false;
  std::vector<double> coefficients;     // POV-Ray's term order
};

// The primitive of a poly placed by `world_from_object`; material, object index and flags are left to the caller.
Primitive make_poly(const Poly& poly, const Matrix& world_from_object);

// A quadric in world space (quadric.cpp): coefficients named as POV-Ray's (a x², e y², h z², b xy, c xz, f yz, d x,
// g y, i z, j).
struct QuadricData : ShapeData {
  double a = 0, b = 0, c = 0, d = 0, e = 0, f = 0, g = 0, h = 0, i = 0, j = 0;
};
// The primitive of a quadric with its transforms folded into the coefficients (it needs no matrix of its own).
Primitive make_quadric(const Quadric& quadric, const Matrix& world_from_object);

namespace shapes {
double poly_value(const PolyData& d, Vec3 object_point);
}  // namespace shapes

}  // namespace povtrace::render
