// Text and value helpers shared by the option files (options.cpp, option_table.cpp, ini_files.cpp): case-blind
// comparisons, strict number parsing and the UsageError messages. Internal to app/.
#pragma once

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <optional>
#include <string>
#include <string_view>
#include <system_error>

#include "app/options.hpp"

namespace povtrace::app::detail {

using std::string_view;

inline char lower_char(char c) { return static_cast<char>(std::tolower(static_cast<unsigned char>(c))); }

inline bool iequals(string_view a, string_view b) {
  return a.size() == b.size() &&
         std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) { return lower_char(x) == lower_char(y); });
}

inline bool istarts_with(string_view text, string_view prefix) {
  return text.size() >= prefix.size() && iequals(text.substr(0, prefix.size()), prefix);
}

inline bool iends_with(string_view text, string_view suffix) {
  return text.size() >= suffix.size() && iequals(text.substr(text.size() - suffix.size()), suffix);
}

inline bool is_space(char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; }

inline string_view trim(string_view s) {
  while (!s.empty() && is_space(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_space(s.back())) s.remove_suffix(1);
  return s;
}

inline string_view unquote(string_view s) {
  if (s.size() >= 2 && s.front() == '"' && s.back() == '"') return s.substr(1, s.size() - 2);
  return s;
}

inline bool is_identifier(string_view s) {
  auto word_char = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_'; };
  return !s.empty() && !std::isdigit(static_cast<unsigned char>(s.front())) &&
         std::all_of(s.begin(), s.end(), word_char);
}

inline std::string in_quotes(string_view s) { return "'" + std::string(s) + "'"; }

[[noreturn]] inline void fail(string_view context, const std::string& message) {
  throw UsageError(std::string(context) + ": " + message);
}

[[noreturn]] inline void unknown_option(string_view written) {
  throw UsageError("unknown option " + in_quotes(written));
}

// Every number must be the whole text: "320" but not "320px", " 320" or "3.2e2" for an integer.
inline std::optional<long long> parse_integer(string_view s) {
  long long value = 0;
  const auto [end, error] = std::from_chars(s.data(), s.data() + s.size(), value);
  if (s.empty() || error != std::errc{} || end != s.data() + s.size()) return std::nullopt;
  return value;
}

inline std::optional<double> parse_real(string_view s) {
  double value = 0.0;
  const auto [end, error] = std::from_chars(s.data(), s.data() + s.size(), value);
  if (s.empty() || error != std::errc{} || end != s.data() + s.size() || !std::isfinite(value)) return std::nullopt;
  return value;
}

inline int integer_in(string_view value, string_view context, int lo, int hi) {
  const std::optional<long long> n = parse_integer(value);
  if (!n || *n < lo || *n > hi) {
    fail(context, "expected a whole number from " + std::to_string(lo) + " to " + std::to_string(hi) + ", got " +
                      in_quotes(value));
  }
  return static_cast<int>(*n);
}

// POV-Ray clips these rather than rejecting them (+R12 renders with depth 9).
inline int clipped_integer(string_view value, string_view context, int lo, int hi) {
  const std::optional<long long> n = parse_integer(value);
  if (!n) fail(context, "expected a whole number, got " + in_quotes(value));
  return static_cast<int>(std::clamp<long long>(*n, lo, hi));
}

inline double real(string_view value, string_view context) {
  const std::optional<double> x = parse_real(value);
  if (!x) fail(context, "expected a number, got " + in_quotes(value));
  return *x;
}

inline double clipped_unit(string_view value, string_view context) {
  return std::clamp(real(value, context), 0.0, 1.0);
}

inline bool boolean(string_view value, string_view context) {
  for (string_view yes : {"on", "true", "yes", "1"}) {
    if (iequals(value, yes)) return true;
  }
  for (string_view no : {"off", "false", "no", "0"}) {
    if (iequals(value, no)) return false;
  }
  fail(context, "expected on/off, true/false, yes/no or 1/0, got " + in_quotes(value));
}

inline std::string non_empty(string_view value, string_view context, string_view what) {
  if (value.empty()) fail(context, "missing " + std::string(what));
  return std::string(value);
}

// A setter takes the value text and a context naming where it came from ("+Wabc", "a.ini:3: Width").
using Setter = void (*)(RenderOptions&, string_view value, string_view context);
// A switch handler: `on` is the sign ('+' true), `value` the text after the letters, `written` the whole switch.
using SwitchHandler = void (*)(RenderOptions&, bool on, string_view value, string_view written);

// Setters kept by name for the long options (option_table.cpp).
void set_input(RenderOptions& o, string_view v, string_view c);
void set_output(RenderOptions& o, string_view v, string_view c);
void set_width(RenderOptions& o, string_view v, string_view c);
void set_height(RenderOptions& o, string_view v, string_view c);
void set_threshold(RenderOptions& o, string_view v, string_view c);
void set_aa_depth(RenderOptions& o, string_view v, string_view c);
void set_sampling(RenderOptions& o, string_view v, string_view c);
void set_jitter_amount(RenderOptions& o, string_view v, string_view c);
void add_library(RenderOptions& o, string_view v, string_view c);
void set_threads(RenderOptions& o, string_view v, string_view c);
void add_declare(RenderOptions& o, string_view v, string_view c);

// The .ini key `key` applied with `value` (Include_Ini reads a file: `depth` limits nesting). False when the
// key is unknown.
bool apply_ini_key(string_view key, string_view value, string_view context, RenderOptions& o, int depth);

// One POV-Ray switch ("+W320", "-A", "+KFF20"): the longest matching letters win. Throws UsageError.
void apply_pov_switch(string_view written, RenderOptions& o);

// Reads an .ini file (or the part of it before the first section plus `section`), in place (ini_files.cpp).
void apply_ini(const std::filesystem::path& ini, const std::optional<std::string>& section, RenderOptions& o,
               int depth);

// Whether `path` should have been read as an .ini reference ("x.ini", "x.ini[Sec]").
struct IniReference {
  std::filesystem::path path;
  std::optional<std::string> section;
};
std::optional<IniReference> as_ini_reference(string_view arg);

// Adds "KEY has no effect in povtrace" once per key; `quiet` settings (from the automatic povray.ini) add none.
void note_no_effect(RenderOptions& o, string_view key, string_view why = {});

}  // namespace povtrace::app::detail
