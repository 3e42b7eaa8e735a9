#include "runtime/jitter.hpp"

#include <array>
#include <cmath>

namespace povtrace {
namespace {

constexpr int parity(unsigned v) {
  int p = 0;
  for (; v != 0; v &= v - 1) p ^= 1;
  return p;
}

// POV-Ray's table is 256 floats written with six decimals. The rule that gives every one of them: with p the
// parity of i and m = i xor 2i (i times 3 without carries), the 15-bit number n = (p·2^14) xor (m·2^6) xor p
// (mod 2^15) makes the value n/2^15 − 0.5, rounded to six decimals with halves away from zero (eight entries are
// such halves), then read as a float. Checked once against all 256 values of POV-Ray 3.7's jitter.cpp (not copied).
std::array<float, 256> make_jitter_table() {
  std::array<float, 256> t{};
  for (unsigned i = 0; i < 256; ++i) {
    const unsigned p = static_cast<unsigned>(parity(i));
    const unsigned n = ((p << 14) ^ ((i ^ (i << 1)) << 6) ^ p) & 0x7FFFu;
    // (n − 2^14)/2^15 · 10^6 is exact in double: 10^6/2^15 = 30.517578125 has nine fractional bits.
    const double micro = std::round((static_cast<double>(n) - 16384.0) * 30.517578125);
    t[i] = static_cast<float>(micro / 1e6);
  }
  return t;
}

const std::array<float, 256>& jitter_table() {
  static const std::array<float, 256> table = make_jitter_table();
  return table;
}

// POV-Ray converts a position to an int (truncating) after scaling it by a prime.
int scaled(double v, double prime) { return static_cast<int>(v * prime); }

double lookup(int a, int b) {
  const int first = lattice_permutation_entry(a & 0xfff);
  return jitter_table_entry(lattice_permutation_entry((first ^ b) & 0xfff) & 0xff);
}

}  // namespace

float jitter_table_entry(int i) { return jitter_table()[static_cast<std::size_t>(i & 0xff)]; }

std::pair<double, double> povray_jitter2d(double x, double y) {
  // Two lookups with the primes 1021 and 1019 swapped between x and y (jitter.h).
  return {lookup(scaled(x, 1021.0), scaled(y, 1019.0)), lookup(scaled(x, 1019.0), scaled(y, 1021.0))};
}

}  // namespace povtrace
