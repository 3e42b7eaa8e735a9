// Features povtrace parses but does not render yet (docs/parser-split-plan.md step S11; unsupported.cpp says how
// they are skipped and refused). It owns no state: it reads the reader and reports through ParserPart.
//
// Public interface (the parts, through ParserPart, and the scene statements): skip_unsupported, skip_balanced,
// refuse_if_unsupported, taint.
#pragma once

#include <string>
#include <string_view>

#include "parser/parser_part.hpp"

namespace povtrace::sdl {

class UnsupportedFeatures : ParserPart {
 public:
  explicit UnsupportedFeatures(Interpreter& in) : ParserPart(in) {}

  UnsupportedFeature skip_unsupported(const Token& keyword, const std::string& what);
  void skip_balanced(const Token& open);
  void refuse_if_unsupported(const Unsupported& u, const SourceLoc& placed_at, std::string_view what) const;
  static void taint(Unsupported& slot, const Unsupported& feature) {
    if (!slot && feature) slot = feature;   // the first one found is the one reported
  }

 private:
  bool continues_arguments(const Token& t);
};

}  // namespace povtrace::sdl
