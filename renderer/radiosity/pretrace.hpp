// The radiosity pretrace's geometry (docs/issue19-study.md §2; POV-Ray 3.7 source/backend/scene/view.cpp, the
// pretrace set-up, and source/backend/render/radiositytask.cpp): how many passes, the cell size of each, which
// jittered positions a block traces in a pass, and when a block (or one of its adaptive sub-blocks) needs no
// further pass. Pure functions of plain values; renderer/pretrace_run.cpp schedules the passes on threads.
#pragma once

#include <array>
#include <deque>
#include <vector>

namespace povtrace::render::radiosity {

// The cell sizes in pixels of the pretrace passes, first to last (study §2.1): with m = max(W, H),
// start = m·pretrace_start, end = max(1, m·pretrace_end), ⌊log2(start/end) + 1 − 1e−10⌋ + 1 passes (at most 252,
// the first pass then starting at end·2^251), pass p having max(start·0.5^p, end).
std::vector<double> pretrace_cell_sizes(int width, int height, double pretrace_start, double pretrace_end);

// POV-Ray's pretrace jitter: a fixed cycle of 2047 values in [−1, 1) (the first outputs of a Mersenne Twister
// mt19937 with its default seed, each u/2^32·2 − 1), read sequentially from a seed index; every read first
// advances the index (so the first value read after seed(i) is entry i + 1).
class PretraceJitter {
 public:
  static constexpr int size = 2047;
  PretraceJitter();
  // The index for block `serial` in pretrace pass `pass` (1-based): pass·17 + serial·13.
  void seed(int pass, int serial);
  double next();
  static const std::array<double, size>& table();

 private:
  int index_ = 0;
};

// An adaptive pretrace sub-block: its column and row among the block's current subdivision.
struct SubBlock {
  int x = 0, y = 0;
};

// A pretrace position in the continuous pixel convention of camera_ray (integer = pixel centre).
struct PretracePoint {
  double x = 0, y = 0;
};

// What a block still has to do in the pretrace (radiositytask.cpp's block info): its subdivision and the
// sub-blocks that asked for another pass, in order. A fresh block is one sub-block covering it.
struct PretraceBlockState {
  int pass = 0;                   // passes done
  int sub_count_x = 1, sub_count_y = 1;
  std::deque<SubBlock> incomplete{SubBlock{}};
  bool finished(int passes) const { return pass >= passes || incomplete.empty(); }
};

// A block of the render grid: inclusive pixel bounds.
struct BlockRect {
  int left = 0, top = 0, right = 0, bottom = 0;
  int width() const { return right - left + 1; }
  int height() const { return bottom - top + 1; }
};

// The positions sub-block `sub` of `block` traces with cell size `size` (study §2.2): the global grid of
// multiples of `size` from the first one at or after left − ½ (top − ½), points with grid coordinates inside
// [sub start, sub end), rows outer, each at grid + (size − 1)/2 + min(1, size/2)·jitter. The y jitter is drawn
// before the x jitter: POV-Ray draws both in one call's arguments, which GCC (Debian's compiler for povray)
// evaluates right to left. The grid coordinates accumulate by repeated addition, as POV-Ray steps them.
std::vector<PretracePoint> pretrace_points(const BlockRect& block, const PretraceBlockState& state, SubBlock sub,
                                           double size, PretraceJitter& jitter);

// Whether a sub-block needs another pass (study §2.4): fewer than 9 points traced → yes; no depth-0 radiosity
// query → no; adaptive coverage A ≠ 0 (nearest_count's second value) reached by the average 4·Σw per query → no;
// otherwise yes.
bool pretrace_again(int points, long queries, float reuse, int coverage);

// How many sub-blocks per axis each sub-block that goes on is split into for the next pass: with adaptive
// pretrace, as many as keep ≥ 4 next-pass points across each (max(1, ⌊next_points / (sub_count·4)⌋)); else 1.
// next_points is ⌊(extent + next_size − 1)/next_size⌋ for the block's width (height).
int pretrace_split(int extent, double next_size, int sub_count, int coverage);

}  // namespace povtrace::render::radiosity
