#pragma once
#include <string_view>

namespace povtrace::sdl {
// True for the 503 reserved words of POV-Ray 3.7 (case-sensitive: `Red` is an identifier, `red` is not).
bool is_reserved_word(std::string_view word);
}  // namespace povtrace::sdl
