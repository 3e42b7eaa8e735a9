// Radiosity's SDL, as POV-Ray 3.7's parser reads it (docs/issue19-study.md §1; pov: parse.cpp, the radiosity items
// of Parse_Global_Settings, Parse_Default and Parse_Object_Mods, and the checks at the end of Parse). The range
// checks and messages are POV-Ray's, with the value found added; each error points at the offending value.
#include <algorithm>
#include <cstdio>
#include <limits>
#include <string>

#include "parser/expressions/int_cast.hpp"
#include "parser/interpreter.hpp"
#include "parser/statements/radiosity_parser.hpp"

namespace povtrace::sdl {

namespace {
constexpr std::string_view kSettingWords =
    "a radiosity setting (adc_bailout, always_sample, brightness, count, error_bound, gray_threshold, load_file, "
    "low_error_factor, max_sample, maximum_reuse, media, minimum_reuse, nearest_count, normal, pretrace_end, "
    "pretrace_start, recursion_limit, save_file, subsurface) or '}'";

std::string number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.10g", v);
  return text;
}

std::string found(double v) { return " (found " + number(v) + ")"; }

// POV-Ray converts these settings with a C cast: the value is truncated before it is checked.
std::string found_integer(double v, int n) {
  if (v == static_cast<double>(n)) return found(v);
  return " (found " + number(v) + ", which counts as " + std::to_string(n) + ")";
}

// The float settings that must be positive, with POV-Ray's message for each.
struct PositiveSetting {
  std::string_view word;
  double RadiositySettings::*field;
  const char* message;
};
constexpr PositiveSetting kPositive[] = {
    {"adc_bailout", &RadiositySettings::adc_bailout, "ADC Bailout must be a positive number"},
    {"brightness", &RadiositySettings::brightness, "Radiosity brightness must be a positive number"},
    {"error_bound", &RadiositySettings::error_bound, "Radiosity error bound must be a positive number"},
    {"low_error_factor", &RadiositySettings::low_error_factor, "Radiosity low error factor must be a positive number"},
    {"maximum_reuse", &RadiositySettings::maximum_reuse, "Radiosity maximum reuse must be a positive number"},
};

// The on/off settings. POV-Ray reads a required float and truncates it: `normal 0.5` is off (not `> 0` as for
// object flags such as no_radiosity).
struct SwitchSetting {
  std::string_view word;
  bool RadiositySettings::*field;
};
constexpr SwitchSetting kSwitches[] = {{"always_sample", &RadiositySettings::always_sample},
                                       {"normal", &RadiositySettings::normal},
                                       {"media", &RadiositySettings::media},
                                       {"subsurface", &RadiositySettings::subsurface}};
}  // namespace

void RadiosityParser::parse_settings(const Token& keyword, std::optional<RadiositySettings>& settings) {
  if (!settings) {
    // POV-Ray's note for scenes written for 3.1 and older, where the block alone did not turn radiosity on.
    if (language_version() < 350)
      warn(keyword.loc, "In POV-Ray 3.5 and later a radiosity{}-block will automatically turn on radiosity if the "
                        "output quality is set to 9 or higher.");
    settings.emplace();
    settings->loc = keyword.loc;
  }
  expect("{", " after 'radiosity'");
  for (Token t = next(); !t.is("}"); t = next())
    if (!parse_item(t, *settings)) fail_expected(t, kSettingWords);
}

bool RadiosityParser::parse_item(const Token& t, RadiositySettings& s) {
  if (t.kind != TokenKind::identifier) return false;
  if (t.is("count")) parse_count(s);
  else if (t.is("nearest_count")) parse_nearest_count(s);
  else if (t.is("max_sample")) s.max_sample = parse_float();   // any value; only > 0 has an effect
  else if (t.is("load_file") || t.is("save_file")) ignored_file_item(t);
  else return parse_limit_item(t, s) || parse_switch_item(t, s);
  return true;
}

// The settings with a range.
bool RadiosityParser::parse_limit_item(const Token& t, RadiositySettings& s) {
  for (const PositiveSetting& p : kPositive)
    if (t.is(p.word)) {
      s.*p.field = positive(p.message);
      if (t.is("maximum_reuse")) maximum_reuse_.at = t.loc;
      return true;
    }
  if (t.is("minimum_reuse")) {
    const Token at = peek();
    s.minimum_reuse = parse_float();
    if (!(s.minimum_reuse >= 0))
      fail_at(at, "Radiosity minimum reuse can not be a negative number" + found(s.minimum_reuse));
    minimum_reuse_.at = t.loc;
  } else if (t.is("gray_threshold")) {
    const Token at = peek();
    s.gray_threshold = parse_float();
    if (!(s.gray_threshold >= 0 && s.gray_threshold <= 1))
      fail_at(at, "Radiosity gray threshold must be from 0.0 to 1.0" + found(s.gray_threshold));
  } else if (t.is("pretrace_start")) {
    s.pretrace_start = fraction("Radiosity pretrace start must be greater than 0 and no higher than 1");
    pretrace_start_.at = t.loc;
  } else if (t.is("pretrace_end")) {
    s.pretrace_end = fraction("Radiosity pretrace end must be greater than 0 and no higher than 1");
    pretrace_end_.at = t.loc;
  } else if (t.is("recursion_limit")) {
    s.recursion_limit = integer_in(1, kRadiosityMaxRecursionLimit,
                                   "Radiosity recursion limit must be in the range 1 to " +
                                       std::to_string(kRadiosityMaxRecursionLimit));
  } else {
    return false;
  }
  return true;
}

bool RadiosityParser::parse_switch_item(const Token& t, RadiositySettings& s) {
  for (const SwitchSetting& w : kSwitches)
    if (t.is(w.word)) {
      s.*w.field = saturating_cast<int>(parse_float()) != 0;
      return true;
    }
  return false;
}

// count N [, M]: M, the direction pool, is max(1600, N) when not written — each time count is written.
void RadiosityParser::parse_count(RadiositySettings& s) {
  s.count = integer_in(1, std::numeric_limits<int>::max(), "Radiosity count must be a positive number");
  accept(",");
  const Token at = peek();
  const double pool = optional_float(std::max(kRadiosityTableDirections, s.count));
  s.direction_pool = saturating_cast<int>(pool);
  if (s.direction_pool < s.count)
    fail_at(at, "Radiosity count can not be more than direction pool size (count 2nd value)" +
                    found_integer(pool, s.direction_pool) + "; count is " + std::to_string(s.count));
}

// nearest_count K [, A]: A, the adaptive pretrace's threshold, is 0 (off) when not written.
void RadiosityParser::parse_nearest_count(RadiositySettings& s) {
  s.nearest_count = integer_in(1, kRadiosityMaxNearestCount, "Radiosity nearest count must be a value from 1 to " +
                                                                std::to_string(kRadiosityMaxNearestCount));
  accept(",");
  const Token at = peek();
  const double adaptive = optional_float(0.0);
  s.nearest_count_adaptive = saturating_cast<int>(adaptive);
  if (s.nearest_count_adaptive < 0 || s.nearest_count_adaptive >= s.nearest_count)
    fail_at(at, "Radiosity nearest count for adaptive pretrace must be non-negative and smaller than general "
                "nearest count" + found_integer(adaptive, s.nearest_count_adaptive) + "; nearest count is " +
                std::to_string(s.nearest_count));
}

double RadiosityParser::positive(const std::string& message) {
  const Token at = peek();
  const double v = parse_float();
  if (!(v > 0)) fail_at(at, message + found(v));
  return v;
}

double RadiosityParser::fraction(const std::string& message) {
  const Token at = peek();
  const double v = parse_float();
  if (!(v > 0 && v <= 1)) fail_at(at, message + found(v));
  return v;
}

int RadiosityParser::integer_in(int low, int high, const std::string& message) {
  const Token at = peek();
  const double v = parse_float();
  const int n = saturating_cast<int>(v);
  if (n < low || n > high) fail_at(at, message + found_integer(v, n));
  return n;
}

// In 3.7 the cache file is a command-line option; POV-Ray reads the string, ignores it and says so.
void RadiosityParser::ignored_file_item(const Token& t) {
  const std::string word(t.text);
  warn(t.loc, "Possible error: In POV-Ray 3.7 and later '" + word + "' has to be specified as an option on the "
              "command-line or in an INI file (" + (word == "load_file" ? "+RFI" : "+RFO") +
              " and +RF<file>); the '" + word + "' setting here is ignored (as in POV-Ray).");
  (void)parse_string();
}

std::optional<double> RadiosityParser::parse_importance(const Token& keyword) {
  (void)keyword;
  expect("{", " after 'radiosity'");
  std::optional<double> importance;
  for (Token t = next(); !t.is("}"); t = next()) {
    if (!t.is("importance")) fail_expected(t, "importance or '}' in radiosity { }");
    const Token at = peek();
    const double v = parse_float();
    if (!(v > 0 && v <= 1)) fail_at(at, "Radiosity importance must be greater than 0.0 and at most 1.0" + found(v));
    importance = v;
  }
  return importance;
}

// POV-Ray checks these once the whole scene is read (blocks in several global_settings add up), so its messages
// have no position; povtrace points at the item written that makes the pair wrong.
void RadiosityParser::finish(std::optional<RadiositySettings>& settings) const {
  if (!settings) return;
  RadiositySettings& s = *settings;
  if (s.pretrace_end > s.pretrace_start)
    fail(pretrace_end_.at.value_or(pretrace_start_.at.value_or(s.loc)),
         "Radiosity pretrace end must be smaller than or equal to pretrace start (pretrace_end " +
             number(s.pretrace_end) + ", pretrace_start " + number(s.pretrace_start) + ")");
  fix_reuse(s);
}

// minimum_reuse must stay below half of maximum_reuse: POV-Ray moves the one the scene did not write, warns when it
// wrote both, and refuses minimum ≥ maximum.
void RadiosityParser::fix_reuse(RadiositySettings& s) const {
  if (!(s.minimum_reuse > s.maximum_reuse * 0.5)) return;
  const std::string advice = "Radiosity maximum_reuse should be significantly larger than minimum_reuse";
  char value[32];
  if (!minimum_reuse_.at) {
    s.minimum_reuse = s.maximum_reuse * 0.5;
    std::snprintf(value, sizeof value, "%f", s.minimum_reuse);
    warn(maximum_reuse_.at.value_or(s.loc),
         advice + ". Decreasing minimum_reuse to " + value + " instead of the default.");
  } else if (!maximum_reuse_.at) {
    s.maximum_reuse = s.minimum_reuse * 2.0;
    std::snprintf(value, sizeof value, "%f", s.maximum_reuse);
    warn(*minimum_reuse_.at, advice + ". Increasing maximum_reuse to " + value + " instead of the default.");
  } else if (s.minimum_reuse >= s.maximum_reuse) {
    fail(*maximum_reuse_.at, "Radiosity maximum_reuse must be larger than minimum_reuse (maximum_reuse " +
                                 number(s.maximum_reuse) + "; minimum_reuse " + number(s.minimum_reuse) +
                                 ", written at " + minimum_reuse_.at->to_string() + ")");
  } else {
    warn(*maximum_reuse_.at, advice + " (maximum_reuse " + number(s.maximum_reuse) + ", minimum_reuse " +
                                 number(s.minimum_reuse) + ").");
  }
}

}  // namespace povtrace::sdl
