// Lattice noise with the structure of POV-Ray 3.7's Noise()/DNoise() and the Turbulence()/DTurbulence() octave
// sums built on them (texture.cpp). POV-Ray's own noise reads a hard-coded table of random numbers that povtrace
// does not copy, so values differ point by point from POV-Ray's; the range, centre, lattice spacing, smoothing and
// the turbulence sums are the same, so noise-based patterns look the same in character.
#pragma once

#include "parser/description.hpp"

namespace povtrace::render {

// POV-Ray's noise generators: 1 is the original clipped noise, 2 the range-corrected one (the default for
// #version 3.5 and later).
enum class NoiseGenerator { original = 1, range_corrected = 2 };

// POV-Ray's Hash3d: the lattice permutation applied to x, then to that xor y, then to that xor z (each of x, y, z
// wrapped to 12 bits): a value in 0..4095 per integer cell.
std::size_t lattice_hash3(long long x, long long y, long long z);

// Scalar noise in [0, 1], centred on 0.5: smooth (an S-curve blend of the 8 lattice corners around the point, each
// corner contributing a constant plus a linear ramp), with unit lattice spacing.
double noise(Vec3 p, NoiseGenerator generator);

// Vector noise: three independent smooth components of the same construction, each roughly in [−1, 1].
Vec3 vector_noise(Vec3 p);

// Fractal sum of `octaves` noise values at frequencies lambda^k and weights omega^k (Turbulence()).
double turbulence(Vec3 p, const Turbulence& t, NoiseGenerator generator);

// The same sum of vector noise (DTurbulence()): the displacement turbulence applies to a point.
Vec3 vector_turbulence(Vec3 p, const Turbulence& t);

}  // namespace povtrace::render
