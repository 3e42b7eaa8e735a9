// The colour map a pattern uses when its pigment gives none (POV-Ray 3.7 texture/pigment.cpp, Post_Pigment).
#pragma once

#include <vector>

#include "scene/description.hpp"

namespace povtrace::render {

// The built-in map of a pigment's pattern. Only the exponent-2 mandel has a map of its own (an exponent changes
// POV-Ray's pattern type, and the others fall back to grey).
const std::vector<MapEntry>& default_colour_map(const Pigment& pigment);

}  // namespace povtrace::render
