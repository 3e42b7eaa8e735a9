#include "app/messages.hpp"

#include <iostream>
#include <map>
#include <stdexcept>

namespace povtrace::app {

Messages::Messages() = default;

Messages::Messages(const MessageStreams& s) {
  const std::ios::openmode mode = s.append ? std::ios::app : std::ios::trunc;
  std::map<std::filesystem::path, std::shared_ptr<std::ofstream>> opened;  // one handle per file named twice
  auto open = [&](const std::optional<std::filesystem::path>& path) -> std::shared_ptr<std::ofstream> {
    if (!path) return nullptr;
    auto& file = opened[*path];
    if (!file) {
      file = std::make_shared<std::ofstream>(*path, std::ios::out | mode);
      if (!*file) throw std::runtime_error("cannot open the message file '" + path->string() + "'");
    }
    return file;
  };
  const MessageStream* streams[5] = {&s.debug, &s.fatal, &s.render, &s.statistics, &s.warning};
  for (int i = 0; i < 5; ++i) targets_[i] = Target{streams[i]->console, open(streams[i]->file)};
  all_file_ = open(s.all_file);
}

Messages::Messages(Captured& captured) : captured_(&captured) {
  for (Target& t : targets_) t.console = false;
}

bool Messages::console(Stream stream) const { return targets_[static_cast<int>(stream)].console; }

void Messages::write(Stream stream, const std::string& text) {
  if (captured_ != nullptr) {
    captured_->emplace_back(stream, text);
    return;
  }
  const Target& t = targets_[static_cast<int>(stream)];
  const bool raw = stream == Stream::debug;
  const std::string line = raw || text.ends_with('\n') ? text : text + "\n";
  if (t.console) std::cerr << line << std::flush;
  if (t.file) *t.file << line << std::flush;
  if (all_file_ && all_file_ != t.file) *all_file_ << line << std::flush;
}

void DebugLines::add(const std::string& text) {
  for (char c : text) {
    if (c == '\n' || c == '\r') {
      messages_.write(Stream::debug, pending_ + "\n");
      pending_.clear();
    } else {
      pending_ += c;
    }
  }
}

}  // namespace povtrace::app
