// The table of POV-Ray 3.7's switches and INI keys (app/option_table.cpp): a row per setting with its switch
// letters, INI key, handlers and what povtrace does with it. --help's switch list, docs/switches.md, the man
// page and the table tests are all made from these rows. Internal to app/.
#pragma once

#include <span>

#include "app/option_text.hpp"

namespace povtrace::app::detail {

inline constexpr int kMaxIniNesting = 16;  // .ini files that name other .ini files; stops cycles

enum class Effect {
  implemented,  // povtrace does what POV-Ray does
  parsed,       // parsed into RenderOptions; the effect is made elsewhere (animation, regions, writers, quality)
  no_effect,    // accepted; a warning says it has no effect in povtrace
};

enum class Warn { never, always, when_on };  // when the no-effect warning is given

struct OptionRow {
  string_view switch_letters;  // "" when there is no switch
  string_view ini_key;
  SwitchHandler on_switch;     // null when there is no switch
  Setter on_ini;
  Effect effect;
  Warn warn;
  string_view description;
};

std::span<const OptionRow> option_rows();

}  // namespace povtrace::app::detail
