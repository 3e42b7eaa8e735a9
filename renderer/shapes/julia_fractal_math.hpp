// POV-Ray 3.7's julia_fractal in its own object space (docs: docs/issue21-julia-fractal.md, written anew from POV-Ray's
// fractal.cpp, quatern.cpp and hcmplx.cpp): the 4-D iteration of quaternions or hypercomplex numbers, the march
// along a ray with bisection, the normal from the orbit and the inside test, in POV-Ray's order of operations.
// renderer/shapes/julia_fractal.cpp places it in the scene (transforms, hits, normals).
#pragma once

#include <cstdint>
#include <vector>

#include "scene/vecmath.hpp"

namespace povtrace::render::julia {

enum class Algebra : std::uint8_t { quaternion, hypercomplex };
enum class Function : std::uint8_t {
  sqr, cube, reciprocal, exp, ln, sin, asin, cos, acos, tan, atan, sinh, asinh, cosh, acosh, tanh, atanh, pwr
};

struct Fractal {
  double c[4] = {1, 0, 0, 0};       // the julia parameter
  Algebra algebra = Algebra::quaternion;
  Function function = Function::sqr;
  double exponent[2] = {0, 0};      // pwr(x, y)
  int max_iteration = 20;
  double precision = 1.0 / 20.0;    // the march step: 1 / the SDL precision
  double slice[4] = {0, 0, 0, 1};   // normalised
  double slice_distance = 0;
  // Set by prepare(): the bounding sphere's radius and its square, and the escape threshold.
  double radius = 0, radius2 = 0, exit_value = 0;
};

// Computes radius, radius2 and exit_value (POV-Ray's Compute_BBox).
void prepare(Fractal& f);

struct FractalHit {
  double depth = 0;   // along the unit object-space direction
  Vec3 point;         // object space
  Vec3 normal;        // object space, not normalised
};

// The hits of the object-space ray origin + t·direction (direction of unit length), in the order found: the first
// only, or every one (a CSG child or a clipped fractal, whose later depths lag as POV-Ray's do), appended to `out`.
void intersect(const Fractal& f, Vec3 origin, Vec3 direction, bool all_hits, std::vector<FractalHit>& out);

// POV-Ray's Fractal::Inside without the inversion (the caller applies it).
bool inside(const Fractal& f, Vec3 point);

}  // namespace povtrace::render::julia
