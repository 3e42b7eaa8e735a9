// Render-ready data of a polynomial surface (poly.cpp), and its construction from the scene description.
#pragma once

#include <vector>

#include "parser/description.hpp"
#include "renderer/geometry.hpp"

namespace povtrace::render {

struct PolyData : ShapeData {
  static constexpr int max_order = 4;   // what the renderer solves (the parser refuses higher orders)
  int order = 4;
  bool sturm = false;
  std::vector<double> coefficients;     // POV-Ray's term order
};

// The primitive of a poly placed by `world_from_object`; material, object index and flags are left to the caller.
Primitive make_poly(const Poly& poly, const Matrix& world_from_object);

namespace shapes {
double poly_value(const PolyData& d, Vec3 object_point);
}  // namespace shapes

}  // namespace povtrace::render
