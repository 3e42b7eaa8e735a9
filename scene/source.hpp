// Source files and diagnostics. Every error the front end reports names file:line:column, shows the source
// line with a caret under the column, and says what was expected (STYLE.md (b) "Throw; don't exit").
#pragma once

#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "scene/source_location.hpp"

namespace povtrace {

// One file's text, kept in memory for the whole parse (macros and loops replay it, errors quote it).
struct SourceFile {
  FileName name;  // as shown in messages
  std::filesystem::path path;
  std::string text;

  // The text of line `line` (1-based), without its line terminator (empty for a line that starts in a released
  // range).
  std::string_view line_text(int line) const;

  // Gives the memory of [begin, end) back to the system, whole pages inside it only: the caller guarantees that
  // nothing reads those bytes again (the literal items of a mesh once read from the text, which no loop can
  // replay; parser/lexing/mesh_scan.hpp). A million-triangle `mesh {}` is 112 MB of text, most of its peak memory.
  // The bytes then read as zeros; line numbers are still counted across them. Ranges are released in order.
  void release(std::size_t begin, std::size_t end);

 private:
  struct Released {
    std::size_t begin = 0, end = 0;   // page-aligned offsets into text
    int newlines = 0;                 // the line breaks the range held
  };
  std::vector<Released> released_;
};

// The one exception type of the front end: a located error with a fully formatted message. `context` is how the
// error was reached ("  in macro M called from f.pov:3:1", "  included from f.pov:1:1", innermost first, one per
// line); what() shows it after the caret block.
class ParseError : public std::runtime_error {
 public:
  ParseError(const SourceLoc& loc, const std::string& message, std::string line_text = {},
             const std::string& context = {});
  // `inner` with `context` appended (for errors raised below the interpreter, e.g. by the lexer).
  ParseError(const ParseError& inner, const std::string& context);
  const SourceLoc& location() const { return loc_; }
  const std::string& bare_message() const { return message_; }
  const std::string& context() const { return context_; }

 private:
  std::shared_ptr<FileNames> file_names_;   // holds loc_'s file name: the error outlives the parse
  SourceLoc loc_;
  std::string message_;
  std::string context_;
};

// "file:line:col: error: message\n<line>\n    ^" (the caret line is omitted when the line is unknown).
std::string format_diagnostic(const SourceLoc& loc, std::string_view severity, std::string_view message,
                              std::string_view line_text);

// Reads a whole file; throws std::runtime_error naming the path when it cannot be read.
std::string read_text_file(const std::filesystem::path& path);

}  // namespace povtrace
