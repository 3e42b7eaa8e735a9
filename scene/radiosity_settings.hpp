// global_settings { radiosity { … } } as POV-Ray 3.7 leaves it after parsing (docs/issue19-study.md §1): every
// setting with POV-Ray's default, already range-checked and fixed up by the parser (the minimum_reuse/maximum_reuse
// pair). Plain data: what each value does in the render is told in the study's sections cited per field.
#pragma once

#include "scene/source_location.hpp"

namespace povtrace {

// POV-Ray's limits on the settings (radiosity.h: MAX_NEAREST_COUNT, DEPTH_MAX, and the size of its built-in table
// of sample directions, which is also the smallest default direction pool).
inline constexpr int kRadiosityMaxNearestCount = 20;
inline constexpr int kRadiosityMaxRecursionLimit = 20;
inline constexpr int kRadiosityTableDirections = 1600;

struct RadiositySettings {
  // The first `radiosity` keyword in global_settings: povtrace refuses to render radiosity there (the renderer does
  // not compute it yet, and must not render the scene without it).
  SourceLoc loc;
  double adc_bailout = 0.01;        // > 0; the bailout of sample rays (§4.4)
  bool always_sample = false;       // final pass gathers too when the reuse weight is short (§3.4)
  double brightness = 1.0;          // > 0; scales what radiosity returns, and the sample rays' base weight
  int count = 35;                   // > 0; rays per new sample at depth 0
  // count's second value: M, the direction pool; M ≥ count. Writing `count N` alone sets it to max(1600, N).
  // M < 1600 means POV-Ray's table, else a Halton(2,3) pool (§5).
  int direction_pool = kRadiosityTableDirections;
  double error_bound = 1.8;         // > 0
  double gray_threshold = 0.0;      // [0, 1]
  double low_error_factor = 0.5;    // > 0; error_bound × this in the pretrace
  double max_sample = -1.0;         // any; only values > 0 clamp a sample ray's colour
  // The reuse pair after POV-Ray's post-parse fix-up (minimum ≤ maximum/2 unless both were written, then
  // minimum < maximum): the parser applies it, so these are the values the render uses.
  double maximum_reuse = 0.2;       // > 0
  double minimum_reuse = 0.015;     // ≥ 0
  int nearest_count = 5;            // 1 … 20
  int nearest_count_adaptive = 0;   // nearest_count's second value: 0 ≤ A < nearest_count; ≠ 0 = adaptive pretrace
  int recursion_limit = 2;          // 1 … 20
  bool normal = false;              // sample frames use the perturbed normal
  bool media = false;               // sample rays compute media
  bool subsurface = false;          // sample rays compute subsurface transport
  double pretrace_start = 0.08;     // (0, 1], fraction of max(width, height)
  double pretrace_end = 0.04;       // (0, 1], ≤ pretrace_start
};

}  // namespace povtrace
