// Errors the renderer finds in a scene while building it (an image file that cannot be read, a palette setting
// the image does not allow): reported like the parser's, at the position written in the scene, with that line.
#pragma once

#include <string>

#include "scene/source.hpp"

namespace povtrace::render {

// Throws a ParseError at `at`, quoting the scene line when the file can still be read.
[[noreturn]] void fail_at_scene(const SourceLoc& at, const std::string& message);

}  // namespace povtrace::render
