// Render options from POV-Ray switches, .ini files and GNU-style long options, all written into one
// RenderOptions. The POV-Ray switches and INI keys are rows of one table (app/option_table.cpp); .ini files are
// read by app/ini_files.cpp; this file holds the long options, the command line, the output name and --help.

#include "app/options.hpp"

#include <iostream>
#include <sstream>

#include "app/option_table.hpp"

namespace povtrace::app {
namespace {

namespace fs = std::filesystem;
using namespace detail;

constexpr string_view kDefaultInput = "object.pov";  // POV-Ray's Input_File_Name default
constexpr string_view kVersion = "0.18";              // povtrace's version

void set_stats(RenderOptions& o, string_view v, string_view c) { o.stats_json = non_empty(v, c, "file name"); }

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
    {"switch-table", Arg::none, [](RenderOptions& o, string_view, string_view) { o.print = RenderOptions::Print::switch_table; }},
    {"man-page", Arg::none, [](RenderOptions& o, string_view, string_view) { o.print = RenderOptions::Print::man_page; }},
    {"version", Arg::none, [](RenderOptions& o, string_view, string_view) { o.version = true; }},
    {"radiosity-povray-order", Arg::none,
     [](RenderOptions& o, string_view, string_view) { o.radiosity_povray_order = true; }},
    {"allow-shellout", Arg::none, [](RenderOptions& o, string_view, string_view) { o.allow_shellout = true; }},
    {"no-povray-ini", Arg::none, [](RenderOptions&, string_view, string_view) {}},  // seen by parse_command_line
    {"benchmark", Arg::none,
     [](RenderOptions& o, string_view, string_view) { note_no_effect(o, "--benchmark", "POV-Ray's built-in benchmark"); }},
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

// `Key=Value` as an argument: POV-Ray accepts any .ini setting on its command line (Width=320, Declare=N=1).
std::optional<std::pair<string_view, string_view>> as_ini_setting(string_view arg) {
  const size_t eq = arg.find('=');
  if (eq == string_view::npos || !is_identifier(trim(arg.substr(0, eq)))) return std::nullopt;
  return std::pair{trim(arg.substr(0, eq)), unquote(trim(arg.substr(eq + 1)))};
}

// ---- Command line ----------------------------------------------------------------------------------

// POV-Ray's unix X options (povray(1)): a preview window povtrace does not have. All but -icon take a value.
constexpr string_view kXOptions[] = {"-display", "-geometry", "-title", "-visual", "-icon"};

bool is_x_option(string_view arg) {
  return std::find(std::begin(kXOptions), std::end(kXOptions), arg) != std::end(kXOptions);
}

bool is_option(string_view arg) {
  return (!arg.empty() && (arg.front() == '+' || arg.front() == '-')) || as_ini_setting(arg).has_value();
}

// POV-Ray's positional words (processrenderoptions.cpp, ProcessUnknownString): a name ending in '/' is a
// library folder, an .ini name (also `file.ini[Section]`) is read in place; anything else is the scene
// (POV-Ray reads other names as INI files too; povtrace takes them as the scene, so `scene.txt` still
// renders). povray also takes a second scene, povtrace refuses it.
void apply_positional(const std::string& arg, RenderOptions& o, bool& scene_seen) {
  if (const std::optional<IniReference> ini = as_ini_reference(arg)) {
    apply_ini(ini->path, ini->section, o, 0);
    return;
  }
  if (arg.size() > 1 && arg.back() == '/') {
    o.library_paths.emplace_back(arg);
    return;
  }
  if (scene_seen) {
    throw UsageError("more than one scene file: " + in_quotes(o.input.string()) + " and " + in_quotes(arg));
  }
  o.input = non_empty(arg, "scene file", "name");
  scene_seen = true;
}

// ---- Output file ----------------------------------------------------------------------------------

// POV-Ray's default extension for each output type (imageprocessing.cpp, GetOutputFilename).
string_view extension_of(image::FileFormat format) {
  switch (format) {
    case image::FileFormat::png: return ".png";
    case image::FileFormat::exr: return ".exr";
    case image::FileFormat::ppm: return ".ppm";
    case image::FileFormat::tga:
    case image::FileFormat::tga_rle: return ".tga";
    case image::FileFormat::jpeg: return ".jpg";
    case image::FileFormat::bmp: return ".bmp";
    case image::FileFormat::hdr: return ".hdr";
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
  if (text == "--V" || text == "-version") {  // POV-Ray's unix spellings of --version
    options.version = true;
    return;
  }
  if (text.starts_with("--")) return apply_long_option(text, std::nullopt, options);
  if (text == "-h" || text == "-?" || text == "-help") {
    options.help = true;
    return;
  }
  if (text == "-benchmark") return apply_long_option("--benchmark", std::nullopt, options);
  if (text.size() >= 2 && (text.front() == '+' || text.front() == '-')) return apply_pov_switch(text, options);
  if (const auto setting = as_ini_setting(text)) {
    if (!apply_ini_key(setting->first, setting->second, text, options, 0)) unknown_option(text);
    return;
  }
  unknown_option(text);
}

void apply_ini_file(const fs::path& ini, RenderOptions& options) { apply_ini(ini, std::nullopt, options, 0); }

void apply_ini_section(const fs::path& ini, const std::string& section, RenderOptions& options) {
  apply_ini(ini, section, options, 0);
}

// The povray.ini (if any) first, then the arguments left to right, so later ones win. `--` ends the options.
// Settings of the automatic povray.ini that povtrace cannot honour (Debian's sets Display=On) give no warning:
// they are the installation's, not this command's.
RenderOptions parse_command_line(int argc, const char* const* argv, const IniEnvironment* environment) {
  RenderOptions options;
  const bool skip_ini = std::any_of(argv + std::min(argc, 1), argv + argc,
                                    [](const char* a) { return string_view(a) == "--no-povray-ini"; });
  if (environment != nullptr && !skip_ini) {
    if (environment->povini && !fs::exists(*environment->povini)) {
      options.warnings.push_back("$POVINI names '" + *environment->povini + "', which cannot be read; ignored");
    }
    if (const std::optional<fs::path> ini = find_povray_ini(*environment)) {
      apply_ini(*ini, std::nullopt, options, 0);
      std::erase_if(options.warnings, [](const std::string& w) { return w.find("has no effect") != std::string::npos; });
    }
  }
  bool options_ended = false;
  bool scene_seen = false;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (!options_ended && is_x_option(arg)) {
      if (arg != "-icon" && ++i >= argc) fail(arg, "needs a value");
      note_no_effect(options, arg, "X preview window option");
    } else if (options_ended || !is_option(arg)) {
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
// "-" (+O-, standard output) stays "-".
fs::path resolved_output_path(const RenderOptions& options) {
  const image::FileFormat format = resolved_format(options);
  if (!options.output) return default_file_name(options, format);
  if (*options.output == "-") return *options.output;
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
    // POV-Ray clips Bits_Per_Color to 5-16 (imageprocessing.cpp).
    encoding.bits_per_channel = std::clamp(options.bits_per_channel, 5, 16);
  }
  encoding.grayscale = options.grayscale;
  encoding.jpeg_quality = options.compression;  // the JPEG writer maps 0 and 1 to 85, as POV-Ray
  encoding.file_gamma = options.file_gamma;
  encoding.dither = options.dither;
  return encoding;
}

std::string version_text() {
  return "povtrace " + std::string(kVersion) +
         "\nA renderer for POV-Ray 3.7 scene files: reads POV-Ray 3.7's scene language, switches and INI files.\n";
}

std::string usage_text() {
  const RenderOptions d;
  std::ostringstream out;
  out << "usage: povtrace [options] scene.pov [file.ini | file.ini[Section] | Key=Value | folder/ ...]\n"
         "Options apply left to right; later ones win. The first povray.ini found ($POVINI, ./povray.ini,\n"
         "~/.povray/3.7/povray.ini, /etc/povray/3.7/povray.ini, ~/.povrayrc) is read before them.\n"
         ".ini files are read where they appear; a word ending in '/' adds a library folder.\n"
         "\n"
         "Common POV-Ray switches (letters in any case; '+' turns a feature on, '-' off):\n"
         "  +I<file>        scene file (Input_File_Name); +I- reads the scene from standard input\n"
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
         "  +F[t][bits|g]   file type N (PNG), E (EXR, half float), P (PPM), T C J B H (TGA, compressed\n"
         "                  TGA, JPEG, BMP, Radiance HDR), bits 5-16 (Output_File_Type, Bits_Per_Color);\n"
         "                  default PNG, " << d.bits_per_channel << " bits\n"
         "  -F              render without writing a file (Output_To_File=off)\n"
         "  +UA / -UA       alpha channel (Output_Alpha); default " << on_off(d.output_alpha) << "\n"
         "  +WT<n>          worker threads (Work_Threads); default " << d.threads << " = all cores\n"
         "  +Q<n>           quality 0-9 (Quality); default " << d.quality << "\n"
         "  +K<c> +KFI<n> +KFF<n> +KI<c> +KF<c> +KC +SF<n> +EF<n> +STP<n>   animation settings\n"
         "  +SR +ER +SC +EC region (pixel numbers, or fractions of the image)\n"
         "  +HI<file>       include a file before the scene (Include_Header)\n"
         "  +MV<v>          initial #version (Version); +WL<n> warning level (Warning_Level)\n"
         "  +G{A,D,F,R,S,W}[file]  text streams to the console (+/-) and a file; +GP appends; +GI<file>\n"
         "                  writes the settings as an INI file (Create_Ini)\n"
         "  +D / -D         display (Display), accepted; povtrace has no preview window; default "
      << on_off(d.display) << "\n"
         "  +V / -V         verbose (Verbose); default " << on_off(d.verbose) << "\n"
         "  +P / -P         pause when done (Pause_When_Done), accepted; default " << on_off(d.pause) << "\n"
         "  Declare=N=V     declare the float N, or the string N with Declare=N=\"text\" (Declare); repeatable\n"
         "  *_Command=, *_Return=  shell-out commands (Pre_Scene, Post_Scene, Pre_Frame, Post_Frame,\n"
         "                  User_Abort, Fatal_Error); run only with --allow-shellout\n"
         "Every POV-Ray 3.7 switch and INI key is accepted; those povtrace cannot honour print a warning.\n"
         "The full list: povtrace --switch-table (or docs/switches.md, man povtrace).\n"
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
         "  --radiosity-povray-order  radiosity's final pass in POV-Ray's one-thread order too (on one thread):\n"
         "                      reproduces povray +WT1's radiosity; by default the final pass is parallel\n"
         "  --allow-shellout    run the *_Command shell-outs (otherwise they are reported and skipped)\n"
         "  --no-povray-ini     do not read a povray.ini\n"
         "  --switch-table      print every POV-Ray switch and INI key with what povtrace does (Markdown)\n"
         "  --assemble OUT [+F...] PART...  merge region renders (+SR +ER +SC +EC parts, EXR or PNG) into OUT\n"
         "  --version           print povtrace's version\n"
         "  --help, -h, -?      print this text\n";
  return out.str();
}

namespace {
const char* effect_text(Effect e) {
  switch (e) {
    case Effect::implemented: return "implemented";
    case Effect::parsed: return "parsed; effect made elsewhere";
    case Effect::no_effect: return "accepted with a warning (no effect)";
  }
  return "?";
}
}  // namespace

std::string switch_table_markdown() {
  std::ostringstream out;
  out << "| switch | INI key | povtrace | meaning |\n|---|---|---|---|\n";
  for (const OptionRow& row : option_rows()) {
    out << "| " << (row.switch_letters.empty() ? std::string() : "`+" + std::string(row.switch_letters) + "`")
        << " | " << row.ini_key << " | " << effect_text(row.effect) << " | " << row.description << " |\n";
  }
  out << "| `--help` `-h` `-?` `-help` | | implemented | usage text |\n"
         "| `--version` `-version` `--V` | | implemented | povtrace's version |\n"
         "| `--benchmark` `-benchmark` | | accepted with a warning (no effect) | POV-Ray's built-in benchmark |\n"
         "| `-display` `-geometry` `-title` `-visual` (with a value), `-icon` | | accepted with a warning (no effect)"
         " | X preview window |\n"
         "| positional word | | implemented | `x.ini` / `x.ini[Sec]` INI file, `dir/` library path, else the scene |\n";
  return out.str();
}

std::string man_page() {
  std::ostringstream out;
  out << ".TH POVTRACE 1 \"\" \"povtrace " << kVersion << "\" \"User Commands\"\n"
      << ".SH NAME\npovtrace \\- render POV-Ray 3.7 scene files\n"
      << ".SH SYNOPSIS\n.B povtrace\n[\\fIoptions\\fR] \\fIscene.pov\\fR [\\fIfile.ini\\fR | \\fIKey=Value\\fR ...]\n"
      << ".SH DESCRIPTION\npovtrace reads POV\\-Ray 3.7 scene files and renders them. It takes POV\\-Ray's "
         "switches, INI files and INI keys; settings it cannot honour are accepted with a warning.\n"
      << ".SH OPTIONS\n.nf\n";
  std::string usage = usage_text();
  for (size_t pos = 0; (pos = usage.find('\\', pos)) != std::string::npos; pos += 2) usage.insert(pos, "\\");
  for (size_t pos = 0; (pos = usage.find("\n.", pos)) != std::string::npos; pos += 3) usage.insert(pos + 1, "\\&");
  for (size_t pos = 0; (pos = usage.find("\n'", pos)) != std::string::npos; pos += 3) usage.insert(pos + 1, "\\&");
  out << usage << ".fi\n.SH \"POV-RAY SWITCHES AND INI KEYS\"\n";
  for (const OptionRow& row : option_rows()) {
    out << ".TP\n.B " << (row.switch_letters.empty() ? "" : "+" + std::string(row.switch_letters) + " ")
        << row.ini_key << "\n" << row.description << " (" << effect_text(row.effect) << ")\n";
  }
  out << ".SH FILES\n.I povray.ini\nread first: $POVINI, ./povray.ini, ~/.povray/3.7/povray.ini, "
         "/etc/povray/3.7/povray.ini, ~/.povrayrc (the first found; \\-\\-no\\-povray\\-ini skips it).\n"
      << ".SH EXIT STATUS\n0 success, 1 a bad scene or a failed render, 2 a bad command line.\n"
      << ".SH SEE ALSO\n.BR povray (1)\n";
  return out.str();
}

}  // namespace povtrace::app
