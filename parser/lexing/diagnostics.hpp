// The parse's errors and warnings (docs/parser-split-plan.md, step S3): the message of each kind, the source line
// it points to and how the parse got there (TokenStream::reached_from), where warnings go (ParseOptions).
#pragma once

#include <string>
#include <string_view>

#include "parser/directives/symbols.hpp"
#include "parser/lexing/lexer.hpp"
#include "parser/lexing/token_stream.hpp"
#include "parser/parse_scene.hpp"

namespace povtrace::sdl {

class Diagnostics {
 public:
  // Only kept here, not used, until a message is given.
  Diagnostics(const ParseOptions& options, const TokenStream& stream, const SymbolTable& symbols)
      : options_(options), stream_(stream), symbols_(symbols) {}
  Diagnostics(const Diagnostics&) = delete;
  Diagnostics& operator=(const Diagnostics&) = delete;

  [[noreturn]] void fail(const SourceLoc& loc, const std::string& message) const;
  [[noreturn]] void fail_at(const Token& t, const std::string& message) const;
  [[noreturn]] void fail_expected(const Token& t, std::string_view expected) const;
  [[noreturn]] void fail_unsupported(const Token& t, std::string_view what) const;
  void warn(const SourceLoc& loc, const std::string& message) const;
  std::string describe(const Token& t) const;   // "the number 3", "the float identifier 'A'", "'}'", …

 private:
  const ParseOptions& options_;
  const TokenStream& stream_;
  const SymbolTable& symbols_;
};

}  // namespace povtrace::sdl
