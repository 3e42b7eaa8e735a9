// povtrace's text output as POV-Ray's five streams (+GD +GF +GR +GS +GW, +GA, *_Console, *_File, +GP):
// each line goes to stderr when its stream's console flag is on, and to the stream's file and All_File when
// they are set. Files are opened once per run, replaced or (Append_File) appended to.
#pragma once

#include <fstream>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "app/options.hpp"

namespace povtrace::app {

enum class Stream { debug, fatal, render, statistics, warning };

class Messages {
 public:
  // Console only, every stream on (what povtrace did before the streams existed).
  Messages();
  // Opens the files the options name; throws std::runtime_error naming a file that cannot be opened.
  explicit Messages(const MessageStreams& streams);
  // Writes nothing: every message is appended to `captured` (an MPI worker's, sent to rank 0 to be written).
  // console() is false for every stream, so no progress line is drawn.
  using Captured = std::vector<std::pair<Stream, std::string>>;
  explicit Messages(Captured& captured);

  // One message (a newline is added unless it ends in one; #debug text, already in lines (DebugLines), as it is).
  void write(Stream stream, const std::string& text);
  bool console(Stream stream) const;

 private:
  struct Target {
    bool console = true;
    std::shared_ptr<std::ofstream> file;
  };
  Target targets_[5];
  std::shared_ptr<std::ofstream> all_file_;
  Captured* captured_ = nullptr;
};

// #debug text of one parse, passed on as POV-Ray 3.7 does: its parser keeps the text until a line ends ('\n' or
// '\r', each ending one line) and sends each complete line, which is written with '\n'. Text after the last line
// end is never sent: POV-Ray keeps one such buffer per parse (per frame) and never flushes it, so a scene's final
// `#debug "no newline"` shows nowhere (the portfolio scenes' last "Generated the file: …" line, for one). POV-Ray's
// wrapping of lines longer than 80 characters is not reproduced.
class DebugLines {
 public:
  explicit DebugLines(Messages& messages) : messages_(messages) {}
  void add(const std::string& text);

 private:
  Messages& messages_;
  std::string pending_;
};

}  // namespace povtrace::app
