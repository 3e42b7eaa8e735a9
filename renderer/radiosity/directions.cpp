#include "renderer/radiosity/directions.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace povtrace::render::radiosity {

double radical_inverse(std::uint64_t i, unsigned base) {
  double h = 0;
  double q = 1.0 / base;
  while (i > 0) {
    h += static_cast<double>(i % base) * q;
    i /= base;
    q /= base;
  }
  return h;
}

Vec3 halton_cosine_direction(std::size_t k) {
  const double u = radical_inverse(k + 1, 2);
  // POV-Ray scales the base-3 value onto [0, 2π) as 0 + v·(2π − 0); the same product here.
  const double theta = radical_inverse(k + 1, 3) * (2 * std::numbers::pi);
  const double rho = std::sqrt(u);
  const double x = rho * std::cos(theta);
  const double z = rho * std::sin(theta);
  return {x, std::sqrt(1 - x * x - z * z), z};
}

DirectionPool::DirectionPool(std::size_t m) {
  if (m == 0) throw std::invalid_argument("radiosity direction pool: size must be positive");
  directions_.reserve(m);
  for (std::size_t k = 0; k < m; ++k) directions_.push_back(halton_cosine_direction(k));
}

}  // namespace povtrace::render::radiosity
