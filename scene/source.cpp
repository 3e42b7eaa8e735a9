#include "scene/source.hpp"

#include <sys/mman.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <sstream>

namespace povtrace {

namespace {
// A copy of `loc` whose file name lives in `names` (a pool the error owns, as the parse's may be gone by the time
// the error is read).
SourceLoc kept_in(const SourceLoc& loc, FileNames& names) {
  SourceLoc kept = loc;
  if (loc.file) kept.file = names.intern(*loc.file);
  return kept;
}
}  // namespace

std::string_view SourceFile::line_text(int line) const {
  std::size_t begin = 0;
  std::size_t next_released = 0;
  for (int current = 1; current < line;) {
    const std::size_t stop = next_released < released_.size() ? released_[next_released].begin : text.size();
    const std::size_t newline = text.find('\n', begin);
    if (newline != std::string::npos && newline < stop) {
      begin = newline + 1;
      ++current;
      continue;
    }
    if (next_released == released_.size()) return {};
    // A released range holds zeros: its line breaks are counted from the record instead.
    const Released& r = released_[next_released++];
    if (current + r.newlines >= line) return {};
    current += r.newlines;
    begin = r.end;
  }
  std::size_t end = text.find('\n', begin);
  if (end == std::string::npos) end = text.size();
  if (end > begin && text[end - 1] == '\r') --end;
  return std::string_view(text).substr(begin, end - begin);
}

void SourceFile::release(std::size_t begin, std::size_t end) {
  const auto page = static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
  const auto base = reinterpret_cast<std::uintptr_t>(text.data());
  const std::uintptr_t first = (base + begin + page - 1) / page * page, last = (base + end) / page * page;
  std::uintptr_t from = first;
  if (!released_.empty()) from = std::max(from, base + released_.back().end);   // what is not released yet
  if (end > text.size() || last <= from) return;
  const auto newlines = static_cast<int>(std::count(text.begin() + static_cast<std::ptrdiff_t>(from - base),
                                                    text.begin() + static_cast<std::ptrdiff_t>(last - base), '\n'));
  // The string's own pages (a large text is a mapping of its own, a smaller one lies inside the heap; whole
  // pages inside the text hold nothing the allocator uses): dropped, they read back as zero-filled pages.
  if (madvise(reinterpret_cast<void*>(from), last - from, MADV_DONTNEED) != 0) return;
  if (!released_.empty() && released_.back().end == from - base) {   // one record for a mesh released in steps
    released_.back().end = last - base;
    released_.back().newlines += newlines;
  } else {
    released_.push_back(Released{from - base, last - base, newlines});
  }
}

std::string format_diagnostic(const SourceLoc& loc, std::string_view severity, std::string_view message,
                              std::string_view line_text) {
  std::string out = loc.to_string() + ": " + std::string(severity) + ": " + std::string(message);
  if (!line_text.empty() || loc.column > 0) {
    std::string shown(line_text);
    std::string caret;
    // Keep tabs in the caret line so the caret lines up under the column in a terminal.
    for (int i = 1; i < loc.column && i - 1 < static_cast<int>(shown.size()); ++i)
      caret += shown[i - 1] == '\t' ? '\t' : ' ';
    for (char& c : shown)
      if (static_cast<unsigned char>(c) < 0x20 && c != '\t') c = ' ';  // never echo control bytes
    out += "\n" + shown + "\n" + caret + "^";
  }
  return out;
}

ParseError::ParseError(const SourceLoc& loc, const std::string& message, std::string line_text,
                       const std::string& context)
    : std::runtime_error(format_diagnostic(loc, "error", message, line_text) + (context.empty() ? "" : "\n") + context),
      file_names_(std::make_shared<FileNames>()),
      loc_(kept_in(loc, *file_names_)),
      message_(message),
      context_(context) {}

ParseError::ParseError(const ParseError& inner, const std::string& context)
    : std::runtime_error(std::string(inner.what()) + (context.empty() ? "" : "\n") + context),
      file_names_(inner.file_names_),
      loc_(inner.loc_),
      message_(inner.message_),
      context_(inner.context_.empty() ? context : inner.context_ + "\n" + context) {}

std::string read_text_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot open '" + path.string() + "'");
  // A regular file is read in one piece into a string of its size: copying it through a string stream was a
  // tenth of the parse of a 7 MB scene. Anything else (or a file that grew meanwhile) goes on as a stream.
  std::error_code ec;
  std::string text;
  if (const auto size = std::filesystem::file_size(path, ec); !ec && size > 0) {
    text.resize(static_cast<std::size_t>(size));
    in.read(text.data(), static_cast<std::streamsize>(size));
    text.resize(static_cast<std::size_t>(in.gcount()));
    if (in.bad()) throw std::runtime_error("cannot read '" + path.string() + "'");
    if (!in || in.peek() == std::ifstream::traits_type::eof()) return text;
  }
  std::ostringstream buffer;
  buffer << text;
  buffer << in.rdbuf();
  if (in.bad()) throw std::runtime_error("cannot read '" + path.string() + "'");
  return buffer.str();
}

}  // namespace povtrace
