// Pigment evaluation (povray-sdl-and-geometry.md §11).
#include <cmath>

#include "renderer/tracer.hpp"

namespace povtrace::render {

namespace {
// checker: parity of floor(x+ε)+floor(y+ε)+floor(z+ε); even → first colour ([V sdl_checker]).
constexpr double kCheckerEpsilon = 1e-10;

int checker_index(Vec3 p) {
  const auto sum = static_cast<long long>(std::floor(p.x + kCheckerEpsilon)) +
                   static_cast<long long>(std::floor(p.y + kCheckerEpsilon)) +
                   static_cast<long long>(std::floor(p.z + kCheckerEpsilon));
  return static_cast<int>(sum & 1);
}
}  // namespace

Colour evaluate_pigment(const RenderPigment& pigment, Vec3 world_point) {
  if (pigment.pattern == PatternKind::solid) return pigment.colour;
  const Vec3 p = pigment.transformed ? pigment.pattern_from_world.point(world_point) : world_point;
  return pigment.entries[checker_index(p)];
}

}  // namespace povtrace::render
