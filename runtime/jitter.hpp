// POV-Ray 3.7's deterministic sample jitter (backend/support/jitter.h): antialiasing and focal blur move each sample
// by a pair of offsets looked up from the sample position, so the image is the same run to run and for any thread
// count. Reproducing the lookup makes a jittered +A render match POV-Ray's like an unjittered one.
#pragma once

#include <cstdint>
#include <utility>

namespace povtrace {

// Entry i (0..255) of POV-Ray's 256-value jitter table, in [−0.5, 0.5).
float jitter_table_entry(int i);

// Entry i & 0xfff of POV-Ray's lattice permutation (the noise hash table), as POV-Ray's PseudoRandom reads it.
std::uint16_t lattice_permutation_entry(int i);

// POV-Ray's Jitter2d(DBL x, DBL y, jx, jy): the offsets (each in [−0.5, 0.5)) of a sample at pixel position (x, y).
std::pair<double, double> povray_jitter2d(double x, double y);

}  // namespace povtrace
