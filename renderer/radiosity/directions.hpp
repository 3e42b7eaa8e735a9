// The radiosity direction pool (docs/issue19-study.md §5): M cosine-weighted unit directions around +y, the
// "up" axis that a sample's frame maps onto the surface normal (frame.hpp). POV-Ray 3.7.0.10 uses, for every
// pool size M >= 1600 (so for every scene that writes `count N` only), the first M points of a 2-D Halton
// sequence in bases 2 and 3 mapped onto the hemisphere with cosine density (source/backend/support/
// randomsequences.cpp, HaltonCosWeightedDirectionGenerator, with the bases of GetSubRandomCosWeightedDirection-
// Generator id 0). For M < 1600 it uses a fixed 1600-entry table that povtrace does not ship (study §5.4); the
// caller warns and uses this pool instead.
//
// The pool is built once per render and read-only afterwards, so every thread may read it without locks.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "scene/vecmath.hpp"

namespace povtrace::render::radiosity {

// The radical inverse of i in `base` (the van der Corput digit mirror): digits of i least significant first,
// weighted by 1/base, 1/base², ... Summed in that order in double precision, as POV-Ray's HaltonGenerator
// does, so the result is bit-identical to its values.
double radical_inverse(std::uint64_t i, unsigned base);

// Entry k (0-based) of the pool: u = φ2(k+1), v = φ3(k+1) (POV-Ray's Halton index starts at 1),
// ρ = √u, θ = 2π·v, x = ρ·cos θ, z = ρ·sin θ, y = √(1 − x² − z²). y ≥ 0 is the cosine to the normal.
Vec3 halton_cosine_direction(std::size_t k);

// The first M entries, precomputed. Consumers cycle through it (index mod M, study §4.3).
class DirectionPool {
 public:
  explicit DirectionPool(std::size_t m);   // m > 0 (std::invalid_argument otherwise)

  std::size_t size() const { return directions_.size(); }
  const Vec3& operator[](std::size_t k) const { return directions_[k]; }
  // Entry `index mod M`: the pool read as an endless cycle.
  const Vec3& cyclic(std::size_t index) const { return directions_[index % directions_.size()]; }
  std::span<const Vec3> directions() const { return directions_; }

 private:
  std::vector<Vec3> directions_;
};

// The pool size POV-Ray uses below this reads its legacy table (study §5.1); povtrace substitutes the Halton pool.
inline constexpr std::size_t legacy_table_size = 1600;

}  // namespace povtrace::render::radiosity
