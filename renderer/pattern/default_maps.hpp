// The colour map a pattern uses when its pigment gives none (POV-Ray 3.7 texture/pigment.cpp, Post_Pigment).
#pragma once

#include <vector>

#include "scene/description.hpp"

namespace povtrace::render {

const std::vector<MapEntry>& default_colour_map(PatternKind kind);

}  // namespace povtrace::render
