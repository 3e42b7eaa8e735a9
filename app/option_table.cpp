// POV-Ray 3.7's switches and INI keys: one row per setting (app/option_table.hpp). The switch matcher takes
// the longest matching letters (+HIfile is Include_Header, not Height; +KFF20 is Final_Frame, not Final_Clock).
// Facts from POV-Ray 3.7's source/frontend/processrenderoptions.cpp and Debian's povray(1); where povray's
// behaviour is not obvious, the comment says what Debian's povray 3.7.0.10 did when tried.

#include "app/option_table.hpp"

#include <iterator>

namespace povtrace::app::detail {
namespace {

constexpr int kMaxSide = 65536;                  // pixels per side
constexpr long long kMaxPixels = 1LL << 28;      // pixels per image: 4 GiB of float RGBA already
constexpr int kMaxThreads = 4096;                // +WT; 0 means one per core

void check_pixel_count(const RenderOptions& o, string_view context) {
  if (static_cast<long long>(o.width) * o.height > kMaxPixels) {
    fail(context, std::to_string(o.width) + "x" + std::to_string(o.height) + " exceeds the limit of 2^28 pixels");
  }
}

void flag_only(string_view value, string_view written) {
  if (!value.empty()) unknown_option(written);
}

// ---- Generic validators for settings povtrace only accepts -------------------------------------------

void sw_flag(RenderOptions&, bool, string_view v, string_view w) { flag_only(v, w); }
void sw_int(RenderOptions&, bool, string_view v, string_view w) { clipped_integer(v, w, 0, 1 << 30); }
void sw_optional_int(RenderOptions&, bool, string_view v, string_view w) {
  if (!v.empty()) clipped_integer(v, w, 0, 1 << 30);
}
void sw_text(RenderOptions&, bool, string_view v, string_view w) { non_empty(v, w, "file name"); }
void ini_bool(RenderOptions&, string_view v, string_view c) { boolean(v, c); }
void ini_int(RenderOptions&, string_view v, string_view c) { clipped_integer(v, c, -(1 << 30), 1 << 30); }
void ini_real(RenderOptions&, string_view v, string_view c) { real(v, c); }
void ini_any(RenderOptions&, string_view, string_view) {}
void ini_text(RenderOptions&, string_view v, string_view c) { non_empty(v, c, "value"); }

// Display_Gamma: a number or sRGB, as File_Gamma.
void ini_gamma(RenderOptions&, string_view v, string_view c) {
  if (!iequals(v, "srgb") && real(v, c) <= 0.0) fail(c, "gamma must be positive or sRGB, got " + in_quotes(v));
}

// +D[type][palette]: povray takes a display type and palette letter; povtrace checks they are letters or
// digits (so that +Declare=N=1, which povray rejects, is rejected).
void sw_display(RenderOptions& o, bool on, string_view v, string_view w) {
  if (v.size() > 2 ||
      !std::all_of(v.begin(), v.end(), [](char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0; })) {
    if (istarts_with(v, "eclare=")) fail(w, "write Declare=NAME=VALUE without a sign");
    unknown_option(w);
  }
  o.display = on;
}

// ---- Input ------------------------------------------------------------------------------------------

void sw_input(RenderOptions& o, bool, string_view v, string_view w) { set_input(o, v, w); }
void sw_library(RenderOptions& o, bool, string_view v, string_view w) { add_library(o, v, w); }
void sw_header(RenderOptions& o, bool, string_view v, string_view w) { o.include_header = non_empty(v, w, "file name"); }
// In an INI file an empty value means none (POV-Ray's own Create_Ini writes `Include_Header=`).
void set_header(RenderOptions& o, string_view v, string_view) {
  if (v.empty()) o.include_header.reset();
  else o.include_header = std::string(v);
}
void include_ini(RenderOptions& o, string_view v, string_view c) {
  const std::string name = non_empty(v, c, "file name");
  const std::optional<IniReference> ref = as_ini_reference(name);
  apply_ini(ref ? ref->path : std::filesystem::path(name), ref ? ref->section : std::nullopt, o, 1);
}

// +MV / Version: the #version the parse starts with (POV-Ray accepts 1.0 to its own version).
void set_version(RenderOptions& o, string_view v, string_view c) {
  const double version = real(v, c);
  if (version < 1.0 || version > 3.71) fail(c, "expected a version from 1.0 to 3.7, got " + in_quotes(v));
  o.language_version = version;
}
void sw_version(RenderOptions& o, bool, string_view v, string_view w) { set_version(o, v, w); }

// ---- Output -----------------------------------------------------------------------------------------

void sw_output(RenderOptions& o, bool, string_view v, string_view w) { set_output(o, v, w); }
// Output_File_Name= (empty, as POV-Ray's Create_Ini writes it): the default name.
void set_output_ini(RenderOptions& o, string_view v, string_view c) {
  if (v.empty()) o.output.reset();
  else set_output(o, v, c);
}
void sw_width(RenderOptions& o, bool, string_view v, string_view w) { set_width(o, v, w); }
void sw_height(RenderOptions& o, bool, string_view v, string_view w) { set_height(o, v, w); }

// Bits_Per_Color: POV-Ray clips to 5…16 (imageprocessing.cpp).
void set_bits(RenderOptions& o, string_view v, string_view c) { o.bits_per_channel = clipped_integer(v, c, 5, 16); }

struct FileType {
  char letter;
  image::FileFormat format;
  bool grayscale;  // POV-Ray allows the 'g' modifier (16-bit greyscale) for PNG and PPM only
};
constexpr FileType kFileTypes[] = {
    {'t', image::FileFormat::tga, false},  {'c', image::FileFormat::tga_rle, false},
    {'n', image::FileFormat::png, true},   {'j', image::FileFormat::jpeg, false},
    {'p', image::FileFormat::ppm, true},   {'b', image::FileFormat::bmp, false},
    {'e', image::FileFormat::exr, false},  {'h', image::FileFormat::hdr, false}};

const FileType* file_type(string_view v, string_view c) {
  const auto* type = v.empty() ? std::end(kFileTypes)
                               : std::find_if(std::begin(kFileTypes), std::end(kFileTypes),
                                              [&](FileType t) { return t.letter == lower_char(v.front()); });
  if (type == std::end(kFileTypes)) {
    fail(c, "unknown output file type " + in_quotes(v) +
                " (N = PNG, E = EXR, P = PPM, T = TGA, C = compressed TGA, J = JPEG, B = BMP, H = Radiance HDR)");
  }
  return type;
}

// Output_File_Type: the letter alone (POV-Ray reads the first character); "N16" is accepted as +F's form.
void set_file_type(RenderOptions& o, string_view v, string_view c) {
  const FileType* type = file_type(v, c);
  o.format = type->format;
  if (type->format == image::FileFormat::exr) o.exr_full_float = false;  // +FE is POV-Ray's half-float EXR
  const string_view rest = v.substr(1);
  if (rest.empty()) return;  // without bits the previous count stays, as in povray
  if (lower_char(rest.front()) == 'g' && rest.size() == 1) {
    if (!type->grayscale) fail(c, "greyscale output is supported for PNG and PPM only (as in POV-Ray)");
    o.grayscale = true;
    return;
  }
  set_bits(o, rest, c);
}

// +F[type][bits|g] writes a file, -F[type] does not (povray prints "Output file: Disabled" for -F and -FN).
void sw_file(RenderOptions& o, bool on, string_view v, string_view w) {
  if (!v.empty()) set_file_type(o, v, w);
  o.write_file = on;
}
void set_write_file(RenderOptions& o, string_view v, string_view c) { o.write_file = boolean(v, c); }
void set_grayscale(RenderOptions& o, string_view v, string_view c) { o.grayscale = boolean(v, c); }
// Compression: JPEG quality, clipped to 0…100 (imageprocessing.cpp).
void set_compression(RenderOptions& o, string_view v, string_view c) { o.compression = clipped_integer(v, c, 0, 100); }
void set_alpha(RenderOptions& o, string_view v, string_view c) { o.output_alpha = boolean(v, c); }
void sw_alpha(RenderOptions& o, bool on, string_view v, string_view w) {
  flag_only(v, w);
  o.output_alpha = on;
}

// File_Gamma: a power, or sRGB (nullopt, the default); 1.0 is "neutral".
void set_file_gamma(RenderOptions& o, string_view v, string_view c) {
  if (iequals(v, "srgb")) {
    o.file_gamma.reset();
    return;
  }
  const double gamma = real(v, c);
  if (gamma <= 0.0) fail(c, "gamma must be positive or sRGB, got " + in_quotes(v));
  o.file_gamma = gamma;
}

image::Dither dither_code(string_view v, string_view c) {
  struct Code { string_view name; image::Dither method; };
  static constexpr Code kCodes[] = {{"B2", image::Dither::bayer2},      {"B3", image::Dither::bayer3},
                                    {"B4", image::Dither::bayer4},      {"D1", image::Dither::diffusion1d},
                                    {"D2", image::Dither::diffusion2d}, {"FS", image::Dither::floyd_steinberg}};
  for (const Code& code : kCodes) {
    if (iequals(code.name, v)) return code.method;
  }
  fail(c, "unknown dither method " + in_quotes(v) + " (B2, B3, B4, D1, D2 or FS)");
}

// Dither on uses Dither_Method (POV-Ray's default Floyd-Steinberg); `dither` holds the method in use or none.
void set_dither_on(RenderOptions& o, bool on) { o.dither = on ? o.dither_method : image::Dither::none; }
void set_dither(RenderOptions& o, string_view v, string_view c) { set_dither_on(o, boolean(v, c)); }
void set_dither_method(RenderOptions& o, string_view v, string_view c) {
  o.dither_method = dither_code(v, c);
  if (o.dither != image::Dither::none) o.dither = o.dither_method;
}
void sw_dither(RenderOptions& o, bool on, string_view v, string_view w) {
  if (!v.empty()) o.dither_method = dither_code(v, w);
  set_dither_on(o, on);
}

// ---- Region, continue, quality ------------------------------------------------------------------------

void set_region(std::optional<double>& field, string_view v, string_view c) {
  const double x = real(v, c);
  if (x < 0.0) fail(c, "expected a pixel number or a fraction, got " + in_quotes(v));
  field = x;
}
void set_start_row(RenderOptions& o, string_view v, string_view c) { set_region(o.region.start_row, v, c); }
void set_end_row(RenderOptions& o, string_view v, string_view c) { set_region(o.region.end_row, v, c); }
void set_start_column(RenderOptions& o, string_view v, string_view c) { set_region(o.region.start_column, v, c); }
void set_end_column(RenderOptions& o, string_view v, string_view c) { set_region(o.region.end_column, v, c); }
void sw_start_row(RenderOptions& o, bool, string_view v, string_view w) { set_start_row(o, v, w); }
void sw_end_row(RenderOptions& o, bool, string_view v, string_view w) { set_end_row(o, v, w); }
void sw_start_column(RenderOptions& o, bool, string_view v, string_view w) { set_start_column(o, v, w); }
void sw_end_column(RenderOptions& o, bool, string_view v, string_view w) { set_end_column(o, v, w); }

void set_continue(RenderOptions& o, string_view v, string_view c) { o.continue_trace = boolean(v, c); }
void sw_continue(RenderOptions& o, bool on, string_view v, string_view w) {
  flag_only(v, w);
  o.continue_trace = on;
}

// Quality 0…11; POV-Ray treats 10 and 11 as 9 (view.cpp), and so does povtrace; others are refused.
void set_quality(RenderOptions& o, string_view v, string_view c) { o.quality = std::min(integer_in(v, c, 0, 11), 9); }
void sw_quality(RenderOptions& o, bool, string_view v, string_view w) { set_quality(o, v, w); }

// ---- Antialiasing ---------------------------------------------------------------------------------------

void set_antialias(RenderOptions& o, string_view v, string_view c) { o.antialias = boolean(v, c); }
// +A, +A0.3, -A; povray also keeps the threshold of -A0.3 while turning antialiasing off.
void sw_antialias(RenderOptions& o, bool on, string_view v, string_view w) {
  if (!v.empty()) set_threshold(o, v, w);
  o.antialias = on;
}
void sw_sampling(RenderOptions& o, bool, string_view v, string_view w) { set_sampling(o, v, w); }
void sw_depth(RenderOptions& o, bool, string_view v, string_view w) { set_aa_depth(o, v, w); }

// Antialias_Gamma: a power or sRGB (kept as antialias_gamma_srgb; the power becomes 2.2, sRGB's nearest).
void set_aa_gamma(RenderOptions& o, string_view v, string_view c) {
  if (iequals(v, "srgb")) {
    o.antialias_gamma = 2.2;
    o.antialias_gamma_srgb = true;
    return;
  }
  const double gamma = real(v, c);
  if (gamma <= 0.0) fail(c, "antialias gamma must be positive, got " + in_quotes(v));
  o.antialias_gamma = gamma;
  o.antialias_gamma_srgb = false;
}
void sw_aa_gamma(RenderOptions& o, bool, string_view v, string_view w) { set_aa_gamma(o, v, w); }
void set_jitter(RenderOptions& o, string_view v, string_view c) { o.jitter = boolean(v, c); }
void sw_jitter(RenderOptions& o, bool on, string_view v, string_view w) {
  if (!v.empty()) set_jitter_amount(o, v, w);
  o.jitter = on;
}

// ---- Animation --------------------------------------------------------------------------------------------

void set_clock(RenderOptions& o, string_view v, string_view c) { o.animation.clock = real(v, c); }
void set_initial_clock(RenderOptions& o, string_view v, string_view c) { o.animation.initial_clock = real(v, c); }
void set_final_clock(RenderOptions& o, string_view v, string_view c) { o.animation.final_clock = real(v, c); }
void set_initial_frame(RenderOptions& o, string_view v, string_view c) {
  o.animation.initial_frame = integer_in(v, c, 0, 1 << 30);
}
void set_final_frame(RenderOptions& o, string_view v, string_view c) {
  o.animation.final_frame = integer_in(v, c, 0, 1 << 30);
}
void set_cyclic(RenderOptions& o, string_view v, string_view c) { o.animation.cyclic = boolean(v, c); }
// Subset frames: 0 or at least 1 is a frame number, a value in (0,1) a fraction of the frames.
void set_subset(std::optional<double>& field, string_view v, string_view c) {
  const double x = real(v, c);
  if (x < 0.0) fail(c, "expected a frame number or a fraction, got " + in_quotes(v));
  field = x;
}
void set_subset_start(RenderOptions& o, string_view v, string_view c) { set_subset(o.animation.subset_start, v, c); }
void set_subset_end(RenderOptions& o, string_view v, string_view c) { set_subset(o.animation.subset_end, v, c); }
// Frame_Step: POV-Ray clips it to at least 1.
void set_frame_step(RenderOptions& o, string_view v, string_view c) {
  o.animation.frame_step = clipped_integer(v, c, 1, 1 << 30);
}
void sw_clock(RenderOptions& o, bool, string_view v, string_view w) { set_clock(o, v, w); }
void sw_initial_clock(RenderOptions& o, bool, string_view v, string_view w) { set_initial_clock(o, v, w); }
void sw_final_clock(RenderOptions& o, bool, string_view v, string_view w) { set_final_clock(o, v, w); }
void sw_initial_frame(RenderOptions& o, bool, string_view v, string_view w) { set_initial_frame(o, v, w); }
void sw_final_frame(RenderOptions& o, bool, string_view v, string_view w) { set_final_frame(o, v, w); }
void sw_cyclic(RenderOptions& o, bool on, string_view v, string_view w) {
  flag_only(v, w);
  o.animation.cyclic = on;
}
void sw_subset_start(RenderOptions& o, bool, string_view v, string_view w) { set_subset_start(o, v, w); }
void sw_subset_end(RenderOptions& o, bool, string_view v, string_view w) { set_subset_end(o, v, w); }
void sw_frame_step(RenderOptions& o, bool, string_view v, string_view w) { set_frame_step(o, v, w); }

// ---- Display and misc ---------------------------------------------------------------------------------

void set_display(RenderOptions& o, string_view v, string_view c) { o.display = boolean(v, c); }
void set_pause(RenderOptions& o, string_view v, string_view c) { o.pause = boolean(v, c); }
void sw_pause(RenderOptions& o, bool on, string_view v, string_view w) {
  flag_only(v, w);
  o.pause = on;
}
void set_verbose(RenderOptions& o, string_view v, string_view c) { o.verbose = boolean(v, c); }
void sw_verbose(RenderOptions& o, bool on, string_view v, string_view w) {
  flag_only(v, w);
  o.verbose = on;
}
void sw_threads(RenderOptions& o, bool, string_view v, string_view w) { set_threads(o, v, w); }

// ---- Streams ----------------------------------------------------------------------------------------------

MessageStream& stream(RenderOptions& o, char which) {
  switch (which) {
    case 'd': return o.streams.debug;
    case 'f': return o.streams.fatal;
    case 'r': return o.streams.render;
    case 's': return o.streams.statistics;
    default: return o.streams.warning;
  }
}

void set_all_console(RenderOptions& o, bool on) {
  for (char s : {'d', 'f', 'r', 's', 'w'}) stream(o, s).console = on;
}

// +G<x>[file]: the sign turns the console output on or off; a file name adds a file.
template <char Which>
void sw_stream(RenderOptions& o, bool on, string_view v, string_view) {
  if (Which == 'a') {
    set_all_console(o, on);
    if (!v.empty()) o.streams.all_file = std::string(v);
    return;
  }
  stream(o, Which).console = on;
  if (!v.empty()) stream(o, Which).file = std::string(v);
}
template <char Which>
void set_stream_console(RenderOptions& o, string_view v, string_view c) {
  if (Which == 'a') set_all_console(o, boolean(v, c));
  else stream(o, Which).console = boolean(v, c);
}
template <char Which>
void set_stream_file(RenderOptions& o, string_view v, string_view c) {
  std::optional<std::filesystem::path>& file = Which == 'a' ? o.streams.all_file : stream(o, Which).file;
  const std::string name(v);
  // POV-Ray's INI writer leaves empty or "off" file names for streams without a file.
  if (name.empty() || iequals(name, "off") || iequals(name, "false")) file.reset();
  else file = non_empty(v, c, "file name");
}
void set_append(RenderOptions& o, string_view v, string_view c) { o.streams.append = boolean(v, c); }
void sw_append(RenderOptions& o, bool on, string_view v, string_view w) {
  flag_only(v, w);
  o.streams.append = on;
}
void set_create_ini(RenderOptions& o, string_view v, string_view c) { o.create_ini = non_empty(v, c, "file name"); }
void sw_create_ini(RenderOptions& o, bool, string_view v, string_view w) { set_create_ini(o, v, w); }
// Warning_Level: POV-Ray clips it to 0…9 (scene.cpp).
void set_warning_level(RenderOptions& o, string_view v, string_view c) {
  o.warning_level = clipped_integer(v, c, 0, 9);
}
void sw_warning_level(RenderOptions& o, bool, string_view v, string_view w) { set_warning_level(o, v, w); }

// ---- Shell-out commands -----------------------------------------------------------------------------------

ShellCommand& shell_command(RenderOptions& o, char which) {
  switch (which) {
    case 'S': return o.shell_commands.pre_scene;
    case 's': return o.shell_commands.post_scene;
    case 'F': return o.shell_commands.pre_frame;
    case 'f': return o.shell_commands.post_frame;
    case 'u': return o.shell_commands.user_abort;
    default: return o.shell_commands.fatal_error;
  }
}
template <char Which>
void set_command(RenderOptions& o, string_view v, string_view) {
  shell_command(o, Which).command = std::string(trim(v));
}
// *_Return: one action letter, optionally negated by '-' or '!' (POV-Ray's ReadSpecialOptionHandler).
template <char Which>
void set_return(RenderOptions& o, string_view v, string_view c) {
  ShellCommand& command = shell_command(o, Which);
  const bool negate = !v.empty() && (v.front() == '-' || v.front() == '!');
  const string_view action = negate ? v.substr(1) : v;
  if (action.size() != 1 || string_view("isaquf").find(lower_char(action.front())) == string_view::npos) {
    fail(c, "expected one of i, s, a, q, u, f (optionally after '-' or '!'), got " + in_quotes(v));
  }
  command.action = lower_char(action.front());
  command.negate = negate;
}

// ---- The table ----------------------------------------------------------------------------------------

using enum Effect;

#define NO_EFFECT(sw, key, on_switch, on_ini, warn, what) {sw, key, on_switch, on_ini, no_effect, warn, what}

constexpr OptionRow kRows[] = {
    // Input
    {"I", "Input_File_Name", sw_input, set_input, implemented, Warn::never,
     "scene file; +I- reads the scene from standard input"},
    {"HI", "Include_Header", sw_header, set_header, implemented, Warn::never,
     "file included before the scene (errors name their own file and line)"},
    {"", "Include_Ini", nullptr, include_ini, implemented, Warn::never, "reads another INI file in place"},
    {"L", "Library_Path", sw_library, add_library, implemented, Warn::never, "adds an include folder (cumulative)"},
    {"MV", "Version", sw_version, set_version, implemented, Warn::never,
     "the #version the parse starts with (a #version in the scene overrides it)"},
    {"", "Declare", nullptr, add_declare, implemented, Warn::never,
     "Declare=N=number declares a float, Declare=N=\"text\" a string"},
    // Output
    {"W", "Width", sw_width, set_width, implemented, Warn::never, "image width"},
    {"H", "Height", sw_height, set_height, implemented, Warn::never, "image height"},
    {"O", "Output_File_Name", sw_output, set_output_ini, implemented, Warn::never,
     "output file or folder/; +O- keeps \"-\" (standard output)"},
    {"F", "Output_To_File", sw_file, set_write_file, implemented, Warn::never,
     "+F[type][bits|g] writes a file, -F none"},
    {"", "Output_File_Type", nullptr, set_file_type, implemented, Warn::never,
     "N PNG, E EXR, P PPM, T TGA, C compressed TGA, J JPEG, B BMP, H Radiance HDR"},
    {"", "Bits_Per_Color", nullptr, set_bits, implemented, Warn::never, "bits per channel, clipped to 5-16"},
    {"", "Bits_Per_Colour", nullptr, set_bits, implemented, Warn::never, "as Bits_Per_Color"},
    {"", "Grayscale_Output", nullptr, set_grayscale, implemented, Warn::never, "greyscale PNG/PPM (+FNG)"},
    {"", "Compression", nullptr, set_compression, implemented, Warn::never, "JPEG quality 0-100 (clipped)"},
    {"UA", "Output_Alpha", sw_alpha, set_alpha, implemented, Warn::never, "alpha channel"},
    {"", "File_Gamma", nullptr, set_file_gamma, implemented, Warn::never, "output gamma: a power or sRGB"},
    {"TH", "Dither", sw_dither, set_dither, implemented, Warn::never, "+TH[method] dithering on/off"},
    {"", "Dither_Method", nullptr, set_dither_method, implemented, Warn::never, "B2 B3 B4 D1 D2 FS"},
    NO_EFFECT("", "Display_Gamma", nullptr, ini_gamma, Warn::always, "gamma of the preview display"),
    NO_EFFECT("MI", "Max_Image_Buffer_Memory", sw_int, ini_int, Warn::always, "image buffer memory in MB"),
    // Region, continue, quality
    {"SR", "Start_Row", sw_start_row, set_start_row, implemented, Warn::never, "first row: pixel, or fraction < 1"},
    {"ER", "End_Row", sw_end_row, set_end_row, implemented, Warn::never, "last row: pixel, or fraction <= 1"},
    {"SC", "Start_Column", sw_start_column, set_start_column, implemented, Warn::never,
     "first column: pixel, or fraction < 1"},
    {"EC", "End_Column", sw_end_column, set_end_column, implemented, Warn::never, "last column: pixel, or fraction <= 1"},
    {"C", "Continue_Trace", sw_continue, set_continue, implemented, Warn::never,
     "continue an interrupted render from its .povtrace-state file"},
    {"Q", "Quality", sw_quality, set_quality, implemented, Warn::never, "quality 0-9 (10 and 11 are 9)"},
    // Antialiasing
    {"A", "Antialias", sw_antialias, set_antialias, implemented, Warn::never, "+A[threshold] antialiasing on/off"},
    {"", "Antialias_Threshold", nullptr, set_threshold, implemented, Warn::never, "threshold, clipped to 0-1"},
    {"AM", "Sampling_Method", sw_sampling, set_sampling, implemented, Warn::never, "sampling method 1 or 2"},
    {"AG", "Antialias_Gamma", sw_aa_gamma, set_aa_gamma, implemented, Warn::never,
     "antialias gamma: a power, or sRGB (rendered as 2.2)"},
    {"R", "Antialias_Depth", sw_depth, set_aa_depth, implemented, Warn::never, "depth, clipped to 1-9"},
    {"J", "Jitter", sw_jitter, set_jitter, implemented, Warn::never, "+J[amount] jitter on/off"},
    {"", "Jitter_Amount", nullptr, set_jitter_amount, implemented, Warn::never, "jitter amount, clipped to 0-1"},
    NO_EFFECT("HR", "High_Reproducibility", sw_flag, ini_bool, Warn::when_on, "radiosity determinism"),
    // Animation
    {"K", "Clock", sw_clock, set_clock, implemented, Warn::never, "clock of a single frame"},
    {"KI", "Initial_Clock", sw_initial_clock, set_initial_clock, implemented, Warn::never, "clock of the first frame"},
    {"KF", "Final_Clock", sw_final_clock, set_final_clock, implemented, Warn::never, "clock of the last frame"},
    {"KFI", "Initial_Frame", sw_initial_frame, set_initial_frame, implemented, Warn::never, "first frame number"},
    {"KFF", "Final_Frame", sw_final_frame, set_final_frame, implemented, Warn::never, "last frame number"},
    {"KC", "Cyclic_Animation", sw_cyclic, set_cyclic, implemented, Warn::never, "cyclic animation"},
    {"SF", "Subset_Start_Frame", sw_subset_start, set_subset_start, implemented, Warn::never,
     "first frame rendered: number, or fraction in (0,1)"},
    {"EF", "Subset_End_Frame", sw_subset_end, set_subset_end, implemented, Warn::never,
     "last frame rendered: number, or fraction in (0,1)"},
    {"STP", "Frame_Step", sw_frame_step, set_frame_step, implemented, Warn::never, "render every n-th frame"},
    NO_EFFECT("KLA", "Clockless_Animation", sw_flag, ini_bool, Warn::when_on, "frames without a clock"),
    NO_EFFECT("UF", "Field_Render", sw_flag, ini_bool, Warn::when_on, "interlaced fields"),
    NO_EFFECT("UO", "Odd_Field", sw_flag, ini_bool, Warn::when_on, "odd field first"),
    // Display
    {"D", "Display", sw_display, set_display, no_effect, Warn::when_on, "preview window"},
    NO_EFFECT("", "Video_Mode", nullptr, ini_any, Warn::always, "preview display type"),
    NO_EFFECT("", "Palette", nullptr, ini_any, Warn::always, "preview palette"),
    NO_EFFECT("SP", "Preview_Start_Size", sw_int, ini_int, Warn::always, "mosaic preview start size"),
    NO_EFFECT("EP", "Preview_End_Size", sw_int, ini_int, Warn::always, "mosaic preview end size"),
    NO_EFFECT("UD", "Draw_Vistas", sw_flag, ini_bool, Warn::when_on, "draw vista rectangles"),
    {"P", "Pause_When_Done", sw_pause, set_pause, no_effect, Warn::when_on, "pause when done"},
    NO_EFFECT("X", "Test_Abort", sw_optional_int, ini_bool, Warn::when_on, "+X[n] keyboard abort test"),
    NO_EFFECT("", "Test_Abort_Count", nullptr, ini_int, Warn::always, "keyboard abort test interval"),
    // Tracing
    NO_EFFECT("B", "Bounding", sw_flag, ini_bool, Warn::never, "automatic bounding (povtrace always bounds)"),
    NO_EFFECT("MB", "Bounding_Threshold", sw_optional_int, ini_int, Warn::always,
              "+MB[n] bounding threshold"),
    NO_EFFECT("BM", "Bounding_Method", sw_int, ini_int, Warn::always, "bounding method (1 BVH, 2 BSP)"),
    NO_EFFECT("", "BSP_BaseAccessCost", nullptr, ini_real, Warn::always, "BSP tuning"),
    NO_EFFECT("", "BSP_ChildAccessCost", nullptr, ini_real, Warn::always, "BSP tuning"),
    NO_EFFECT("", "BSP_ISectCost", nullptr, ini_real, Warn::always, "BSP tuning"),
    NO_EFFECT("", "BSP_MaxDepth", nullptr, ini_int, Warn::always, "BSP tuning"),
    NO_EFFECT("", "BSP_MissChance", nullptr, ini_real, Warn::always, "BSP tuning"),
    NO_EFFECT("UR", "Remove_Bounds", sw_flag, ini_bool, Warn::always, "remove unnecessary bounds"),
    NO_EFFECT("SU", "Split_Unions", sw_flag, ini_bool, Warn::always, "split bounded unions"),
    NO_EFFECT("UL", "Light_Buffer", sw_flag, ini_bool, Warn::always, "light buffer (POV-Ray 3.6)"),
    NO_EFFECT("UV", "Vista_Buffer", sw_flag, ini_bool, Warn::always, "vista buffer (POV-Ray 3.6)"),
    NO_EFFECT("BS", "Render_Block_Size", sw_int, ini_int, Warn::always, "block size (povtrace: 32)"),
    NO_EFFECT("RS", "Render_Block_Step", sw_int, ini_int, Warn::always, "block order step"),
    NO_EFFECT("RP", "Render_Pattern", sw_int, ini_int, Warn::always, "block order pattern"),
    {"WT", "Work_Threads", sw_threads, set_threads, implemented, Warn::never, "worker threads (0 = all cores)"},
    // Radiosity and experiments
    NO_EFFECT("RF", "Radiosity_File_Name", sw_text, ini_text, Warn::always, "radiosity cache file"),
    NO_EFFECT("RFI", "Radiosity_From_File", sw_flag, ini_bool, Warn::when_on, "load the radiosity cache"),
    NO_EFFECT("RFO", "Radiosity_To_File", sw_flag, ini_bool, Warn::when_on, "save the radiosity cache"),
    NO_EFFECT("RVP", "Radiosity_Vain_Pretrace", sw_flag, ini_bool, Warn::when_on, "radiosity pretrace"),
    NO_EFFECT("RTR", "Real_Time_Raytracing", sw_flag, ini_bool, Warn::when_on, "real-time raytracing"),
    // Text streams
    {"GA", "All_Console", sw_stream<'a'>, set_stream_console<'a'>, implemented, Warn::never,
     "+GA[file] every stream to the console and a file"},
    {"", "All_File", nullptr, set_stream_file<'a'>, implemented, Warn::never, "file receiving every stream"},
    {"GD", "Debug_Console", sw_stream<'d'>, set_stream_console<'d'>, implemented, Warn::never,
     "+GD[file] #debug text"},
    {"", "Debug_File", nullptr, set_stream_file<'d'>, implemented, Warn::never, "#debug text file"},
    {"GF", "Fatal_Console", sw_stream<'f'>, set_stream_console<'f'>, implemented, Warn::never, "+GF[file] errors"},
    {"", "Fatal_File", nullptr, set_stream_file<'f'>, implemented, Warn::never, "error file"},
    {"GR", "Render_Console", sw_stream<'r'>, set_stream_console<'r'>, implemented, Warn::never,
     "+GR[file] render messages (povtrace's progress and rescaling notes)"},
    {"", "Render_File", nullptr, set_stream_file<'r'>, implemented, Warn::never, "render message file"},
    {"GS", "Statistic_Console", sw_stream<'s'>, set_stream_console<'s'>, implemented, Warn::never,
     "+GS[file] statistics (povtrace's summary line)"},
    {"", "Statistic_File", nullptr, set_stream_file<'s'>, implemented, Warn::never, "statistics file"},
    {"GW", "Warning_Console", sw_stream<'w'>, set_stream_console<'w'>, implemented, Warn::never,
     "+GW[file] warnings"},
    {"", "Warning_File", nullptr, set_stream_file<'w'>, implemented, Warn::never, "warning file"},
    {"GP", "Append_File", sw_append, set_append, implemented, Warn::never, "append to the stream files"},
    {"GI", "Create_Ini", sw_create_ini, set_create_ini, implemented, Warn::never,
     "writes the resolved settings as an INI file"},
    {"WL", "Warning_Level", sw_warning_level, set_warning_level, implemented, Warn::never,
     "0-4 silence the parser's warnings, 5-9 show them (clipped to 0-9)"},
    {"V", "Verbose", sw_verbose, set_verbose, implemented, Warn::never, "verbose messages"},
    // Shell-out commands
    {"", "Pre_Scene_Command", nullptr, set_command<'S'>, implemented, Warn::never,
     "run before the scene (with --allow-shellout)"},
    {"", "Pre_Scene_Return", nullptr, set_return<'S'>, implemented, Warn::never, "action on its exit status"},
    {"", "Post_Scene_Command", nullptr, set_command<'s'>, implemented, Warn::never,
     "run after the scene (with --allow-shellout)"},
    {"", "Post_Scene_Return", nullptr, set_return<'s'>, implemented, Warn::never, "action on its exit status"},
    {"", "Pre_Frame_Command", nullptr, set_command<'F'>, implemented, Warn::never,
     "run before each frame (the frame loop calls it)"},
    {"", "Pre_Frame_Return", nullptr, set_return<'F'>, implemented, Warn::never, "action on its exit status"},
    {"", "Post_Frame_Command", nullptr, set_command<'f'>, implemented, Warn::never,
     "run after each frame (the frame loop calls it)"},
    {"", "Post_Frame_Return", nullptr, set_return<'f'>, implemented, Warn::never, "action on its exit status"},
    {"", "User_Abort_Command", nullptr, set_command<'u'>, implemented, Warn::never,
     "run on Ctrl-C (with --allow-shellout)"},
    {"", "User_Abort_Return", nullptr, set_return<'u'>, implemented, Warn::never, "action on its exit status"},
    {"", "Fatal_Error_Command", nullptr, set_command<'e'>, implemented, Warn::never,
     "run on an error (with --allow-shellout)"},
    {"", "Fatal_Error_Return", nullptr, set_return<'e'>, implemented, Warn::never, "action on its exit status"},
    // Obsolete in POV-Ray 3.7 itself
    NO_EFFECT("", "Buffer_Output", nullptr, ini_any, Warn::always, "obsolete (POV-Ray 3.7 ignores it too)"),
    NO_EFFECT("", "Buffer_Size", nullptr, ini_any, Warn::always, "obsolete (POV-Ray 3.7 ignores it too)"),
    NO_EFFECT("", "Create_Histogram", nullptr, ini_any, Warn::always, "obsolete (POV-Ray 3.7 ignores it too)"),
    NO_EFFECT("", "Histogram_Name", nullptr, ini_any, Warn::always, "obsolete (POV-Ray 3.7 ignores it too)"),
    NO_EFFECT("", "Histogram_Grid_Size", nullptr, ini_any, Warn::always, "obsolete (POV-Ray 3.7 ignores it too)"),
    NO_EFFECT("", "Histogram_Type", nullptr, ini_any, Warn::always, "obsolete (POV-Ray 3.7 ignores it too)"),
};

#undef NO_EFFECT

std::string row_name(const OptionRow& row) {
  if (row.switch_letters.empty()) return std::string(row.ini_key);
  return "+" + std::string(row.switch_letters) + " / " + std::string(row.ini_key);
}

void after_setting(const OptionRow& row, RenderOptions& o, bool on) {
  if (row.warn == Warn::always || (row.warn == Warn::when_on && on)) note_no_effect(o, row_name(row));
}

}  // namespace

std::span<const OptionRow> option_rows() { return kRows; }

void note_no_effect(RenderOptions& o, string_view key, string_view why) {
  std::string text = std::string(key) + " has no effect in povtrace";
  if (!why.empty()) text += " (" + std::string(why) + ")";
  if (std::find(o.warnings.begin(), o.warnings.end(), text) == o.warnings.end()) o.warnings.push_back(text);
}

void apply_pov_switch(string_view written, RenderOptions& o) {
  const string_view body = written.substr(1);
  const OptionRow* best = nullptr;
  for (const OptionRow& row : kRows) {
    if (!row.switch_letters.empty() && istarts_with(body, row.switch_letters) &&
        (best == nullptr || row.switch_letters.size() > best->switch_letters.size())) {
      best = &row;
    }
  }
  if (best == nullptr) unknown_option(written);
  const bool on = written.front() == '+';
  best->on_switch(o, on, body.substr(best->switch_letters.size()), written);
  after_setting(*best, o, on);
}

bool apply_ini_key(string_view key, string_view value, string_view context, RenderOptions& o, int depth) {
  const auto* row = std::find_if(std::begin(kRows), std::end(kRows),
                                 [&](const OptionRow& r) { return iequals(r.ini_key, key); });
  if (row == std::end(kRows)) return false;
  if (row->on_ini == include_ini) {
    if (depth >= kMaxIniNesting) fail(context, ".ini files nested too deeply");
    const std::string name = non_empty(value, context, "file name");
    const std::optional<IniReference> ref = as_ini_reference(name);
    apply_ini(ref ? ref->path : std::filesystem::path(name), ref ? ref->section : std::nullopt, o, depth + 1);
    return true;
  }
  row->on_ini(o, value, context);
  after_setting(*row, o, row->warn == Warn::when_on && boolean(value, context));
  return true;
}

// ---- Setters shared with the long options ---------------------------------------------------------------

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

// Clipped to 0…1. povray clips Antialias_Threshold=5 in an .ini file to 1 but refuses +A1.7 on the command
// line; povtrace clips both, so a command that works with povray works the same here.
void set_threshold(RenderOptions& o, string_view v, string_view c) { o.antialias_threshold = clipped_unit(v, c); }
void set_aa_depth(RenderOptions& o, string_view v, string_view c) { o.antialias_depth = clipped_integer(v, c, 1, 9); }
void set_sampling(RenderOptions& o, string_view v, string_view c) { o.sampling_method = integer_in(v, c, 1, 2); }
void set_jitter_amount(RenderOptions& o, string_view v, string_view c) { o.jitter_amount = clipped_unit(v, c); }
void add_library(RenderOptions& o, string_view v, string_view c) {
  o.library_paths.emplace_back(non_empty(v, c, "folder"));
}
void set_threads(RenderOptions& o, string_view v, string_view c) { o.threads = integer_in(v, c, 0, kMaxThreads); }

// Declare=NAME=VALUE: a float, or a string when the value holds a double quote (POV-Ray takes the text up to
// the next quote). povray quietly declares 0 for a non-number; povtrace refuses it. A later declare of the
// same name replaces one of the other kind.
void add_declare(RenderOptions& o, string_view v, string_view c) {
  const size_t eq = v.find('=');
  if (eq == string_view::npos) fail(c, "expected NAME=VALUE, got " + in_quotes(v));
  const string_view name = trim(v.substr(0, eq));
  const string_view text = trim(v.substr(eq + 1));
  if (!is_identifier(name)) fail(c, in_quotes(name) + " is not an identifier");
  auto named = [&](const auto& d) { return d.first == name; };
  if (const size_t quote = text.find('"'); quote != string_view::npos) {
    string_view value = text.substr(quote + 1);
    value = value.substr(0, value.find('"'));
    std::erase_if(o.declares, named);
    o.string_declares.emplace_back(std::string(name), std::string(value));
    return;
  }
  const std::optional<double> value = parse_real(text);
  if (!value) fail(c, "the value of " + std::string(name) + " must be a number, got " + in_quotes(text));
  std::erase_if(o.string_declares, named);
  o.declares.emplace_back(std::string(name), *value);
}

}  // namespace povtrace::app::detail
