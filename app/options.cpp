// Render options from POV-Ray switches, .ini files and GNU-style long options, all written into one
// RenderOptions. Three tables map a name to a small handler:
//   kSwitches     POV-Ray switches (+W320, -A, +FN16 …), letters matched case-insensitively, longest first;
//   kIniKeys      .ini keys (Width=320 …), also accepted as a bare `Key=Value` argument, as POV-Ray does;
//   kLongOptions  GNU-style options (--width=320 or --width 320).
// .ini keys and long options share the setters below, so a value means the same whichever way it is given.
// Where POV-Ray's behaviour is not obvious, the comment says what Debian's povray 3.7.0.10 did when tried.

#include "app/options.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string_view>
#include <system_error>

namespace povtrace::app {
namespace {

namespace fs = std::filesystem;
using std::string_view;

constexpr int kMaxSide = 65536;                  // pixels per side
constexpr long long kMaxPixels = 1LL << 28;      // pixels per image: 4 GiB of float RGBA already
constexpr int kMaxThreads = 4096;                // +WT; 0 means one per core
constexpr int kMaxIniNesting = 16;               // .ini files that name other .ini files; stops cycles
constexpr string_view kDefaultInput = "object.pov";  // POV-Ray's Input_File_Name default

// ---- Text -----------------------------------------------------------------------------------------

char lower_char(char c) { return static_cast<char>(std::tolower(static_cast<unsigned char>(c))); }

bool iequals(string_view a, string_view b) {
  return a.size() == b.size() &&
         std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) { return lower_char(x) == lower_char(y); });
}

bool istarts_with(string_view text, string_view prefix) {
  return text.size() >= prefix.size() && iequals(text.substr(0, prefix.size()), prefix);
}

bool iends_with(string_view text, string_view suffix) {
  return text.size() >= suffix.size() && iequals(text.substr(text.size() - suffix.size()), suffix);
}

bool is_space(char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; }

string_view trim(string_view s) {
  while (!s.empty() && is_space(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_space(s.back())) s.remove_suffix(1);
  return s;
}

string_view unquote(string_view s) {
  if (s.size() >= 2 && s.front() == '"' && s.back() == '"') return s.substr(1, s.size() - 2);
  return s;
}

bool is_identifier(string_view s) {
  auto word_char = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_'; };
  return !s.empty() && !std::isdigit(static_cast<unsigned char>(s.front())) &&
         std::all_of(s.begin(), s.end(), word_char);
}

std::string in_quotes(string_view s) { return "'" + std::string(s) + "'"; }

[[noreturn]] void fail(string_view context, const std::string& message) {
  throw UsageError(std::string(context) + ": " + message);
}

[[noreturn]] void unknown_option(string_view written) { throw UsageError("unknown option " + in_quotes(written)); }

// ---- Values ---------------------------------------------------------------------------------------
// Every number must be the whole text: "320" but not "320px", " 320" or "3.2e2" for an integer.

std::optional<long long> parse_integer(string_view s) {
  long long value = 0;
  const auto [end, error] = std::from_chars(s.data(), s.data() + s.size(), value);
  if (s.empty() || error != std::errc{} || end != s.data() + s.size()) return std::nullopt;
  return value;
}

std::optional<double> parse_real(string_view s) {
  double value = 0.0;
  const auto [end, error] = std::from_chars(s.data(), s.data() + s.size(), value);
  if (s.empty() || error != std::errc{} || end != s.data() + s.size() || !std::isfinite(value)) return std::nullopt;
  return value;
}

int integer_in(string_view value, string_view context, int lo, int hi) {
  const std::optional<long long> n = parse_integer(value);
  if (!n || *n < lo || *n > hi) {
    fail(context, "expected a whole number from " + std::to_string(lo) + " to " + std::to_string(hi) + ", got " +
                      in_quotes(value));
  }
  return static_cast<int>(*n);
}

// POV-Ray clips these rather than rejecting them (+R12 renders with depth 9).
int clipped_integer(string_view value, string_view context, int lo, int hi) {
  const std::optional<long long> n = parse_integer(value);
  if (!n) fail(context, "expected a whole number, got " + in_quotes(value));
  return static_cast<int>(std::clamp<long long>(*n, lo, hi));
}

double real(string_view value, string_view context) {
  const std::optional<double> x = parse_real(value);
  if (!x) fail(context, "expected a number, got " + in_quotes(value));
  return *x;
}

double clipped_unit(string_view value, string_view context) { return std::clamp(real(value, context), 0.0, 1.0); }

bool boolean(string_view value, string_view context) {
  for (string_view yes : {"on", "true", "yes", "1"}) {
    if (iequals(value, yes)) return true;
  }
  for (string_view no : {"off", "false", "no", "0"}) {
    if (iequals(value, no)) return false;
  }
  fail(context, "expected on/off, true/false, yes/no or 1/0, got " + in_quotes(value));
}

std::string non_empty(string_view value, string_view context, string_view what) {
  if (value.empty()) fail(context, "missing " + std::string(what));
  return std::string(value);
}

// ---- Setters shared by .ini keys and long options ------------------------------------------------
// Each takes the value text and a context naming where it came from ("+Wabc", "a.ini:3: Width").

using Setter = void (*)(RenderOptions&, string_view value, string_view context);

void check_pixel_count(const RenderOptions& o, string_view context) {
  if (static_cast<long long>(o.width) * o.height > kMaxPixels) {
    fail(context, std::to_string(o.width) + "x" + std::to_string(o.height) + " exceeds the limit of 2^28 pixels");
  }
}

void set_input(RenderOptions& o, string_view v, string_view c) { o.input = non_empty(v, c, "file name"); }
void set_output(RenderOptions& o, string_view v, string_view c) { o.output = non_empty(v, c, "file name"); }

void set_width(RenderOptions& o, string_view v, string_view c) {
  o.width = integer_in(v, c, 1, kMaxSide);
  check_pixel_count(o, c);
}

void set_height(RenderOptions& o, string_view v, string_view c) {
  o.height = integer_in(v, c, 1, kMaxSide);
  check_pixel_count(o, c);
}

void set_antialias(RenderOptions& o, string_view v, string_view c) { o.antialias = boolean(v, c); }
// Clipped to 0…1. povray clips Antialias_Threshold=5 in an .ini file to 1 but refuses +A1.7 on the command
// line; povtrace clips both, so a command that works with povray works the same here.
void set_threshold(RenderOptions& o, string_view v, string_view c) { o.antialias_threshold = clipped_unit(v, c); }
void set_aa_depth(RenderOptions& o, string_view v, string_view c) { o.antialias_depth = clipped_integer(v, c, 1, 9); }
void set_sampling(RenderOptions& o, string_view v, string_view c) { o.sampling_method = integer_in(v, c, 1, 2); }
void set_jitter(RenderOptions& o, string_view v, string_view c) { o.jitter = boolean(v, c); }
void set_jitter_amount(RenderOptions& o, string_view v, string_view c) { o.jitter_amount = clipped_unit(v, c); }
void add_library(RenderOptions& o, string_view v, string_view c) {
  o.library_paths.emplace_back(non_empty(v, c, "folder"));
}
void set_alpha(RenderOptions& o, string_view v, string_view c) { o.output_alpha = boolean(v, c); }
void set_write_file(RenderOptions& o, string_view v, string_view c) { o.write_file = boolean(v, c); }
void set_display(RenderOptions& o, string_view v, string_view c) { o.display = boolean(v, c); }
void set_verbose(RenderOptions& o, string_view v, string_view c) { o.verbose = boolean(v, c); }
void set_pause(RenderOptions& o, string_view v, string_view c) { o.pause = boolean(v, c); }
void set_threads(RenderOptions& o, string_view v, string_view c) { o.threads = integer_in(v, c, 0, kMaxThreads); }
void set_stats(RenderOptions& o, string_view v, string_view c) { o.stats_json = non_empty(v, c, "file name"); }

void set_aa_gamma(RenderOptions& o, string_view v, string_view c) {
  const double gamma = real(v, c);
  if (gamma <= 0.0) fail(c, "antialias gamma must be positive, got " + in_quotes(v));
  o.antialias_gamma = gamma;
}

void set_bits(RenderOptions& o, string_view v, string_view c) {
  const std::optional<long long> bits = parse_integer(v);
  if (bits != 8 && bits != 16) fail(c, "bits per channel must be 8 or 16, got " + in_quotes(v));
  o.bits_per_channel = static_cast<int>(*bits);
}

// POV-Ray's file type: a letter and optional bits per channel ("N", "n16", "E", "P16"). povray accepts other
// bit counts (+FN12 writes 36 bpp); our writers do 8 or 16 only, so anything else is rejected.
void set_file_type(RenderOptions& o, string_view v, string_view c) {
  struct Type { char letter; image::FileFormat format; };
  static constexpr Type kTypes[] = {
      {'n', image::FileFormat::png}, {'e', image::FileFormat::exr}, {'p', image::FileFormat::ppm}};
  const auto* type = v.empty() ? std::end(kTypes) : std::find_if(std::begin(kTypes), std::end(kTypes), [&](Type t) {
    return t.letter == lower_char(v.front());
  });
  if (type == std::end(kTypes)) fail(c, "unknown output file type " + in_quotes(v) + " (N = PNG, E = EXR, P = PPM)");
  o.format = type->format;
  const string_view bits = v.substr(1);
  if (type->format == image::FileFormat::exr) {
    o.exr_full_float = false;                   // +FE is POV-Ray's half-float EXR; povray accepts +FE16 too
    if (!bits.empty()) integer_in(bits, c, 1, 32);
    return;
  }
  if (!bits.empty()) set_bits(o, bits, c);      // without bits the previous count stays, as in povray
}

// Declare=NAME=VALUE: POV-Ray's Declare takes a float. povray quietly declares 0 for a non-number.
void add_declare(RenderOptions& o, string_view v, string_view c) {
  const size_t eq = v.find('=');
  if (eq == string_view::npos) fail(c, "expected NAME=VALUE, got " + in_quotes(v));
  const string_view name = trim(v.substr(0, eq));
  const string_view number = trim(v.substr(eq + 1));
  if (!is_identifier(name)) fail(c, in_quotes(name) + " is not an identifier");
  const std::optional<double> value = parse_real(number);
  if (!value) fail(c, "the value of " + std::string(name) + " must be a number, got " + in_quotes(number));
  o.declares.emplace_back(std::string(name), *value);
}

void set_format(RenderOptions& o, string_view v, string_view c) {
  struct Format { string_view name; image::FileFormat format; int bits; bool full_float; };  // bits 0: unchanged
  static constexpr Format kFormats[] = {
      {"png", image::FileFormat::png, 8, false}, {"png16", image::FileFormat::png, 16, false},
      {"exr", image::FileFormat::exr, 0, false}, {"exr32", image::FileFormat::exr, 0, true},
      {"ppm", image::FileFormat::ppm, 8, false}, {"ppm16", image::FileFormat::ppm, 16, false}};
  const auto* f = std::find_if(std::begin(kFormats), std::end(kFormats), [&](Format x) { return iequals(x.name, v); });
  if (f == std::end(kFormats)) fail(c, "expected png, png16, exr, exr32, ppm or ppm16, got " + in_quotes(v));
  o.format = f->format;
  o.exr_full_float = f->full_float;
  if (f->bits != 0) o.bits_per_channel = f->bits;
}

void set_lighting(RenderOptions& o, string_view v, string_view c) {
  if (v == "povray") {
    o.lighting = LightingModel::povray;
  } else if (v == "textbook") {
    o.lighting = LightingModel::textbook;
  } else {
    fail(c, "expected povray or textbook, got " + in_quotes(v));
  }
}

// ---- .ini keys ------------------------------------------------------------------------------------

struct IniKey {
  string_view key;
  Setter apply;
};

constexpr IniKey kIniKeys[] = {
    {"Input_File_Name", set_input},       // relative names stay relative to the working directory, as povray
    {"Output_File_Name", set_output},
    {"Width", set_width},
    {"Height", set_height},
    {"Antialias", set_antialias},
    {"Antialias_Threshold", set_threshold},
    {"Antialias_Depth", set_aa_depth},
    {"Antialias_Gamma", set_aa_gamma},
    {"Sampling_Method", set_sampling},
    {"Jitter", set_jitter},
    {"Jitter_Amount", set_jitter_amount},
    {"Library_Path", add_library},
    {"Output_File_Type", set_file_type},
    {"Output_To_File", set_write_file},
    {"Output_Alpha", set_alpha},
    {"Bits_Per_Color", set_bits},
    {"Declare", add_declare},
    {"Display", set_display},
    {"Verbose", set_verbose},
    {"Pause_When_Done", set_pause},
    {"Work_Threads", set_threads},
};

const IniKey* find_ini_key(string_view key) {
  const auto* found =
      std::find_if(std::begin(kIniKeys), std::end(kIniKeys), [&](const IniKey& k) { return iequals(k.key, key); });
  return found == std::end(kIniKeys) ? nullptr : found;
}

// ---- POV-Ray switches -----------------------------------------------------------------------------
// `on` is the sign ('+' true, '-' false); `value` is the text after the letters; `written` the whole switch.
// Valued switches take their value with either sign, as POV-Ray does.

using SwitchHandler = void (*)(RenderOptions&, bool on, string_view value, string_view written);

void flag_only(string_view value, string_view written) {
  if (!value.empty()) unknown_option(written);
}

void switch_input(RenderOptions& o, bool, string_view v, string_view w) { set_input(o, v, w); }
void switch_output(RenderOptions& o, bool, string_view v, string_view w) { set_output(o, v, w); }
void switch_width(RenderOptions& o, bool, string_view v, string_view w) { set_width(o, v, w); }
void switch_height(RenderOptions& o, bool, string_view v, string_view w) { set_height(o, v, w); }
void switch_depth(RenderOptions& o, bool, string_view v, string_view w) { set_aa_depth(o, v, w); }
void switch_sampling(RenderOptions& o, bool, string_view v, string_view w) { set_sampling(o, v, w); }
void switch_aa_gamma(RenderOptions& o, bool, string_view v, string_view w) { set_aa_gamma(o, v, w); }
void switch_library(RenderOptions& o, bool, string_view v, string_view w) { add_library(o, v, w); }
void switch_threads(RenderOptions& o, bool, string_view v, string_view w) { set_threads(o, v, w); }

// +A, +A0.3, -A; povray also keeps the threshold of -A0.3 while turning antialiasing off.
void switch_antialias(RenderOptions& o, bool on, string_view v, string_view w) {
  if (!v.empty()) set_threshold(o, v, w);
  o.antialias = on;
}

void switch_jitter(RenderOptions& o, bool on, string_view v, string_view w) {
  if (!v.empty()) set_jitter_amount(o, v, w);
  o.jitter = on;
}

// +F[type] writes a file, -F[type] does not (povray prints "Output file: Disabled" for -F and -FN alike).
void switch_file(RenderOptions& o, bool on, string_view v, string_view w) {
  if (!v.empty()) set_file_type(o, v, w);
  o.write_file = on;
}

// povray accepts a display type or palette after +D (-D0, +DG …); povtrace has no display, so it only
// checks that the suffix is letters and digits (so that +Declare=N=1, which povray rejects, is rejected).
void switch_display(RenderOptions& o, bool on, string_view v, string_view w) {
  if (!std::all_of(v.begin(), v.end(), [](char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0; })) {
    if (istarts_with(v, "eclare=")) fail(w, "write Declare=NAME=VALUE without a sign");
    unknown_option(w);
  }
  o.display = on;
}

void switch_alpha(RenderOptions& o, bool on, string_view v, string_view w) {
  flag_only(v, w);
  o.output_alpha = on;
}

void switch_verbose(RenderOptions& o, bool on, string_view v, string_view w) {
  flag_only(v, w);
  o.verbose = on;
}

void switch_pause(RenderOptions& o, bool on, string_view v, string_view w) {
  flag_only(v, w);
  o.pause = on;
}

struct SwitchSpec {
  string_view letters;
  SwitchHandler apply;
};

// Longer letters first: +AM2 is the sampling method, not antialiasing with threshold "M2".
constexpr SwitchSpec kSwitches[] = {
    {"AM", switch_sampling}, {"AG", switch_aa_gamma}, {"A", switch_antialias}, {"WT", switch_threads},
    {"W", switch_width},     {"UA", switch_alpha},    {"D", switch_display},   {"F", switch_file},
    {"H", switch_height},    {"I", switch_input},     {"J", switch_jitter},    {"L", switch_library},
    {"O", switch_output},    {"P", switch_pause},     {"R", switch_depth},     {"V", switch_verbose},
};

void apply_pov_switch(string_view written, RenderOptions& o) {
  const string_view body = written.substr(1);
  for (const SwitchSpec& spec : kSwitches) {
    if (istarts_with(body, spec.letters)) {
      spec.apply(o, written.front() == '+', body.substr(spec.letters.size()), written);
      return;
    }
  }
  unknown_option(written);
}

// ---- Long options ---------------------------------------------------------------------------------

enum class Arg { none, required, optional };

// --no-specialise: every specialised path off; --no-specialise=a,b: those named.
void turn_off_specialisations(RenderOptions& o, string_view v, string_view c) {
  if (v.empty()) v = "all";
  while (!v.empty()) {
    const std::size_t comma = v.find(',');
    const string_view name = v.substr(0, comma);
    // The parser's one specialisation (ParseOptions::expression_programs); the others are the renderer's.
    const bool parser_path = name == "expression-programs" || name == "all";
    if (parser_path) o.expression_programs = false;
    if (!o.specialise.turn_off(name) && !parser_path)
      fail(c, "unknown specialisation " + in_quotes(name) + "; expected all or some of expression-programs, " +
                  render::SpecialisationChoice::names());
    v = comma == string_view::npos ? string_view{} : v.substr(comma + 1);
  }
}

void long_antialias(RenderOptions& o, string_view v, string_view c) {
  if (!v.empty()) set_threshold(o, v, c);
  o.antialias = true;
}

void long_jitter(RenderOptions& o, string_view v, string_view c) {
  if (!v.empty()) set_jitter_amount(o, v, c);
  o.jitter = true;
}

struct LongOption {
  string_view name;
  Arg arg;
  Setter apply;  // flags get an empty value; so do optional values that are left out
};

constexpr LongOption kLongOptions[] = {
    {"input", Arg::required, set_input},
    {"output", Arg::required, set_output},
    {"width", Arg::required, set_width},
    {"height", Arg::required, set_height},
    {"antialias", Arg::optional, long_antialias},
    {"no-antialias", Arg::none, [](RenderOptions& o, string_view, string_view) { o.antialias = false; }},
    {"aa-depth", Arg::required, set_aa_depth},
    {"sampling-method", Arg::required, set_sampling},
    {"jitter", Arg::optional, long_jitter},
    {"no-jitter", Arg::none, [](RenderOptions& o, string_view, string_view) { o.jitter = false; }},
    {"library-path", Arg::required, add_library},
    {"format", Arg::required, set_format},
    {"threads", Arg::required, set_threads},
    {"declare", Arg::required, add_declare},
    {"alpha", Arg::none, [](RenderOptions& o, string_view, string_view) { o.output_alpha = true; }},
    {"stats", Arg::required, set_stats},
    {"vs-povray", Arg::none, [](RenderOptions& o, string_view, string_view) { o.vs_povray = true; }},
    {"lighting", Arg::required, set_lighting},
    {"povray-tolerances", Arg::none, [](RenderOptions& o, string_view, string_view) { o.povray_tolerances = true; }},
    {"no-specialise", Arg::optional, turn_off_specialisations},
    {"help", Arg::none, [](RenderOptions& o, string_view, string_view) { o.help = true; }},
    {"verbose", Arg::none, [](RenderOptions& o, string_view, string_view) { o.verbose = true; }},
};

const LongOption* find_long_option(string_view name) {
  const auto* found = std::find_if(std::begin(kLongOptions), std::end(kLongOptions),
                                   [&](const LongOption& l) { return l.name == name; });
  return found == std::end(kLongOptions) ? nullptr : found;
}

// "--name" or "--name=value"; `separate` is the next argument when the caller took it as the value.
void apply_long_option(string_view written, std::optional<string_view> separate, RenderOptions& o) {
  const string_view body = written.substr(2);
  const size_t eq = body.find('=');
  const LongOption* spec = find_long_option(body.substr(0, eq));
  if (spec == nullptr) unknown_option(written);
  const std::optional<string_view> value = eq != string_view::npos ? std::optional(body.substr(eq + 1)) : separate;
  if (spec->arg == Arg::none && value) fail(written, "takes no value");
  if (spec->arg == Arg::required && !value) fail(written, "needs a value");
  if (spec->arg == Arg::optional && value && value->empty()) fail(written, "empty value");
  spec->apply(o, value.value_or(string_view{}), written);
}

bool takes_separate_value(string_view arg) {
  if (!arg.starts_with("--") || arg.find('=') != string_view::npos) return false;
  const LongOption* spec = find_long_option(arg.substr(2));
  return spec != nullptr && spec->arg == Arg::required;
}

// ---- .ini files -----------------------------------------------------------------------------------

// `Key=Value` as an argument: POV-Ray accepts any .ini setting on its command line (Width=320, Declare=N=1).
std::optional<std::pair<string_view, string_view>> as_ini_setting(string_view arg) {
  const size_t eq = arg.find('=');
  if (eq == string_view::npos || !is_identifier(trim(arg.substr(0, eq)))) return std::nullopt;
  return std::pair{trim(arg.substr(0, eq)), unquote(trim(arg.substr(eq + 1)))};
}

struct IniReference {
  fs::path path;
  std::optional<std::string> section;
};

// "scene.ini" or "scene.ini[Section]" (any case of ".ini").
std::optional<IniReference> as_ini_reference(string_view arg) {
  if (iends_with(arg, ".ini")) return IniReference{fs::path(arg), std::nullopt};
  const size_t open = arg.rfind('[');
  if (arg.ends_with(']') && open != string_view::npos && iends_with(arg.substr(0, open), ".ini")) {
    return IniReference{fs::path(arg.substr(0, open)), std::string(arg.substr(open + 1, arg.size() - open - 2))};
  }
  return std::nullopt;
}

// Drops a ';' comment (outside double quotes), the '\r' of CRLF files and surrounding blanks.
string_view strip_ini_line(string_view line) {
  bool inside_quotes = false;
  for (size_t i = 0; i < line.size(); ++i) {
    if (line[i] == '"') inside_quotes = !inside_quotes;
    if (line[i] == ';' && !inside_quotes) return trim(line.substr(0, i));
  }
  return trim(line);
}

std::vector<string_view> split_blanks(string_view line) {
  std::vector<string_view> words;
  while (!(line = trim(line)).empty()) {
    const auto blank = std::find_if(line.begin(), line.end(), is_space);
    const size_t length = static_cast<size_t>(blank - line.begin());
    words.push_back(line.substr(0, length));
    line.remove_prefix(length);
  }
  return words;
}

void apply_ini(const fs::path& ini, const std::optional<std::string>& section, RenderOptions& o, int depth);

// One non-blank line: Key=Value, one or more switches ("+W320 +H240", as povray allows), or another .ini file.
void apply_ini_line(string_view line, const std::string& where, RenderOptions& o, int depth) {
  if (line.front() == '+' || line.front() == '-') {
    for (string_view word : split_blanks(line)) {
      try {
        apply_switch(std::string(word), o);
      } catch (const UsageError& e) {
        throw UsageError(where + ": " + e.what());
      }
    }
  } else if (const size_t eq = line.find('='); eq != string_view::npos) {
    const string_view key = trim(line.substr(0, eq));
    const IniKey* spec = find_ini_key(key);
    if (spec == nullptr) throw UsageError(where + ": unknown key " + in_quotes(key));
    spec->apply(o, unquote(trim(line.substr(eq + 1))), where + ": " + std::string(key));
  } else if (const std::optional<IniReference> nested = as_ini_reference(unquote(line))) {
    if (depth >= kMaxIniNesting) throw UsageError(where + ": .ini files nested too deeply");
    apply_ini(nested->path, nested->section, o, depth + 1);
  } else {
    throw UsageError(where + ": expected Key=Value, got " + in_quotes(line));
  }
}

// Without a selected section POV-Ray reads only the lines before the first [Section] header (checked with
// povray: a Width under [Sec] is ignored unless the argument is file.ini[Sec]). With one, it reads those
// lines plus every section of that name, compared case-insensitively.
void apply_ini(const fs::path& ini, const std::optional<std::string>& section, RenderOptions& o, int depth) {
  std::error_code error;
  std::ifstream in(ini);
  if (!in || fs::is_directory(ini, error)) throw UsageError("cannot read .ini file " + in_quotes(ini.string()));
  bool reading = true;
  bool section_found = false;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    const string_view text = strip_ini_line(line);
    if (text.empty()) continue;
    if (text.front() == '[') {
      const size_t close = text.find(']');
      reading = section && close != string_view::npos && iequals(trim(text.substr(1, close - 1)), *section);
      section_found = section_found || reading;
    } else if (reading) {
      apply_ini_line(text, ini.string() + ":" + std::to_string(number), o, depth);
    }
  }
  if (in.bad()) throw UsageError("cannot read .ini file " + in_quotes(ini.string()));
  if (section && !section_found) throw UsageError(ini.string() + ": no section [" + *section + "]");
}

// ---- Command line ----------------------------------------------------------------------------------

bool is_option(string_view arg) {
  return (!arg.empty() && (arg.front() == '+' || arg.front() == '-')) || as_ini_setting(arg).has_value();
}

// An .ini file (read now, in place) or the scene; povray also takes a second scene, povtrace refuses it.
void apply_positional(const std::string& arg, RenderOptions& o, bool& scene_seen) {
  if (const std::optional<IniReference> ini = as_ini_reference(arg)) {
    apply_ini(ini->path, ini->section, o, 0);
    return;
  }
  if (scene_seen) {
    throw UsageError("more than one scene file: " + in_quotes(o.input.string()) + " and " + in_quotes(arg));
  }
  o.input = non_empty(arg, "scene file", "name");
  scene_seen = true;
}

// ---- Output file ----------------------------------------------------------------------------------

string_view extension_of(image::FileFormat format) {
  switch (format) {
    case image::FileFormat::png: return ".png";
    case image::FileFormat::exr: return ".exr";
    case image::FileFormat::ppm: return ".ppm";
    default: break;
  }
  return ".png";
}

bool names_folder(const fs::path& path) {
  std::error_code error;
  return !path.has_filename() || fs::is_directory(path, error);
}

image::FileFormat resolved_format(const RenderOptions& o) {
  if (o.format) return *o.format;
  const bool names_file = o.output && !names_folder(*o.output);
  return (names_file ? image::format_from_extension(*o.output) : std::nullopt).value_or(image::FileFormat::png);
}

fs::path default_file_name(const RenderOptions& o, image::FileFormat format) {
  const fs::path input = o.input.empty() ? fs::path(kDefaultInput) : o.input;
  fs::path name = input.stem();
  name += extension_of(format);
  return name;
}

// ---- Help -----------------------------------------------------------------------------------------

std::string on_off(bool value) { return value ? "on" : "off"; }

std::string format_number(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

}  // namespace

// ---- Public functions ------------------------------------------------------------------------------

void apply_switch(const std::string& text, RenderOptions& options) {
  if (text.starts_with("--")) return apply_long_option(text, std::nullopt, options);
  if (text == "-h") {
    options.help = true;
    return;
  }
  if (text.size() >= 2 && (text.front() == '+' || text.front() == '-')) return apply_pov_switch(text, options);
  if (const auto setting = as_ini_setting(text)) {
    const IniKey* spec = find_ini_key(setting->first);
    if (spec == nullptr) unknown_option(text);
    return spec->apply(options, setting->second, text);
  }
  unknown_option(text);
}

void apply_ini_file(const fs::path& ini, RenderOptions& options) { apply_ini(ini, std::nullopt, options, 0); }

void apply_ini_section(const fs::path& ini, const std::string& section, RenderOptions& options) {
  apply_ini(ini, section, options, 0);
}

// Arguments apply left to right, so later ones win. `--` ends the options.
RenderOptions parse_command_line(int argc, const char* const* argv) {
  RenderOptions options;
  bool options_ended = false;
  bool scene_seen = false;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (options_ended || !is_option(arg)) {
      apply_positional(arg, options, scene_seen);
    } else if (arg == "--") {
      options_ended = true;
    } else if (takes_separate_value(arg) || arg == "-o") {
      if (i + 1 >= argc) fail(arg, "needs a value");
      const std::string value = argv[++i];
      if (arg == "-o") set_output(options, value, arg);
      else apply_long_option(arg, value, options);
    } else {
      apply_switch(arg, options);
    }
  }
  return options;
}

// An explicit +O names the file, or the folder for the default name (a trailing '/' or an existing folder).
// Like povray, a name whose extension does not match the format gets the format's extension appended
// (+Oout → out.png, +Oout.exr +FN → out.exr.png); unlike povray, the comparison ignores case (out.PNG).
fs::path resolved_output_path(const RenderOptions& options) {
  const image::FileFormat format = resolved_format(options);
  if (!options.output) return default_file_name(options, format);
  if (names_folder(*options.output)) return *options.output / default_file_name(options, format);
  if (image::format_from_extension(*options.output) == format) return *options.output;
  fs::path path = *options.output;
  path += extension_of(format);
  return path;
}

image::EncodeOptions resolved_encoding(const RenderOptions& options) {
  image::EncodeOptions encoding;
  encoding.format = resolved_format(options);
  if (encoding.format == image::FileFormat::exr) {
    encoding.exr_full_float = options.exr_full_float;
  } else {
    encoding.bits_per_channel = options.bits_per_channel;
  }
  return encoding;
}

std::string usage_text() {
  const RenderOptions d;
  std::ostringstream out;
  out << "usage: povtrace [options] scene.pov [file.ini | file.ini[Section] | Key=Value ...]\n"
         "Options apply left to right; later ones win. .ini files are read where they appear.\n"
         "\n"
         "POV-Ray switches (letters in any case; '+' turns a feature on, '-' off):\n"
         "  +I<file>        scene file (Input_File_Name)\n"
         "  +O<file|dir/>   output file (Output_File_Name); default: scene name + extension, in the\n"
         "                  working directory\n"
         "  +W<n> +H<n>     image size (Width, Height); default " << d.width << "x" << d.height << "\n"
         "  +A[t] / -A[t]   antialiasing on/off (Antialias), optional threshold 0-1 (Antialias_Threshold);\n"
         "                  default " << on_off(d.antialias) << ", threshold "
      << format_number(d.antialias_threshold) << "\n"
         "  +AM<n>          sampling method 1 or 2 (Sampling_Method); default " << d.sampling_method << "\n"
         "  +AG<g>          antialias gamma (Antialias_Gamma); default " << format_number(d.antialias_gamma) << "\n"
         "  +R<n>           antialias depth 1-9 (Antialias_Depth); default " << d.antialias_depth << "\n"
         "  +J[a] / -J      jitter on/off (Jitter), optional amount 0-1 (Jitter_Amount); default "
      << on_off(d.jitter) << ", amount " << format_number(d.jitter_amount) << "\n"
         "  +L<dir>         add a library folder for #include (Library_Path); repeatable\n"
         "  +F[t][bits]     write a file of type N (PNG), E (EXR, half float) or P (PPM), bits 8 or 16\n"
         "                  (Output_File_Type, Bits_Per_Color); default PNG, " << d.bits_per_channel << " bits\n"
         "  -F              render without writing a file (Output_To_File=off)\n"
         "  +UA / -UA       alpha channel (Output_Alpha); default " << on_off(d.output_alpha) << "\n"
         "  +WT<n>          worker threads (Work_Threads); default " << d.threads << " = all cores\n"
         "  +D / -D         display (Display), accepted and ignored; default " << on_off(d.display) << "\n"
         "  +V / -V         verbose (Verbose); default " << on_off(d.verbose) << "\n"
         "  +P / -P         pause when done (Pause_When_Done), accepted and ignored; default "
      << on_off(d.pause) << "\n"
         "  Declare=N=V     declare the float identifier N (Declare); repeatable\n"
         "\n"
         "Long options (--opt=value or --opt value):\n"
         "  --input=FILE, --output=FILE (-o FILE), --width=N, --height=N\n"
         "  --antialias[=T], --no-antialias, --aa-depth=N, --sampling-method=N\n"
         "  --jitter[=A], --no-jitter, --library-path=DIR\n"
         "  --format=png|png16|exr|exr32|ppm|ppm16   exr32 writes full floats; default png\n"
         "  --threads=N, --declare NAME=VALUE, --alpha, --verbose\n"
         "  --stats=FILE.json   write render statistics as JSON\n"
         "  --vs-povray         render with povray too and compare; writes povtrace | POV-Ray | heat map\n"
         "  --lighting=povray|textbook   lighting model; default povray\n"
         "  --povray-tolerances  POV-Ray's absolute tolerances at any scale (no rescaling of very small or very\n"
         "                      large scenes), artefacts included\n"
         "  --no-specialise[=NAME,...]  the general paths instead of those chosen for what the scene holds\n"
         "                      (same image, slower; for measuring what each gains); NAME: all (default),\n"
         "                      nearest-shadow-first, no-shadow-rays, embree-meshes\n"
         "  --assemble OUT [+F...] PART...  merge region renders (+SR +ER +SC +EC parts, EXR or PNG) into OUT\n"
         "  --help, -h          print this text\n";
  return out.str();
}

}  // namespace povtrace::app
