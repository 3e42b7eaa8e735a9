// Radiosity's SDL (docs/issue19-study.md §1): global_settings { radiosity { … } }, the object modifier and the
// #default item `radiosity { importance F }`, and POV-Ray's checks and fix-ups once the whole scene is parsed. Its
// bodies are in radiosity.cpp.
//
// It owns what the post-parse fix-up needs besides the settings themselves: which of minimum_reuse, maximum_reuse,
// pretrace_start and pretrace_end the scene wrote, and where (POV-Ray's minimumReuseSet and maximumReuseSet; the
// positions let the post-parse errors and warnings point at the item that causes them).
//
// Public interface: parse_settings (SceneStatements, inside global_settings), parse_importance (object modifiers
// and #default, through ParserPart), finish (SceneStatements, when the parse ends).
#pragma once

#include <optional>
#include <string>

#include "parser/parser_part.hpp"

namespace povtrace::sdl {

class RadiosityParser : ParserPart {
 public:
  explicit RadiosityParser(Interpreter& in) : ParserPart(in) {}

  // `radiosity { … }` after the keyword: creates the settings at their defaults if this is the scene's first
  // block, then edits them (each item may repeat; the last wins).
  void parse_settings(const Token& keyword, std::optional<RadiositySettings>& settings);
  // `radiosity { [importance F]… }` after the keyword: the last importance written, if any.
  std::optional<double> parse_importance(const Token& keyword);
  // POV-Ray's checks after the parse (pretrace_end ≤ pretrace_start) and the minimum_reuse/maximum_reuse fix-up.
  void finish(std::optional<RadiositySettings>& settings) const;

 private:
  struct Written {   // the position of the last item that wrote a setting, if one did
    std::optional<SourceLoc> at;
  };
  bool parse_item(const Token& t, RadiositySettings& s);
  bool parse_limit_item(const Token& t, RadiositySettings& s);
  bool parse_switch_item(const Token& t, RadiositySettings& s);
  void parse_count(RadiositySettings& s);
  void parse_nearest_count(RadiositySettings& s);
  double positive(const std::string& message);
  int integer_in(int low, int high, const std::string& message);
  double fraction(const std::string& message);
  void ignored_file_item(const Token& t);
  void fix_reuse(RadiositySettings& s) const;

  Written minimum_reuse_, maximum_reuse_, pretrace_start_, pretrace_end_;
};

}  // namespace povtrace::sdl
