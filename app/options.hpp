// Render options from POV-Ray-style switches (+W640, -A, +A0.3, +Lpath …), POV-Ray .ini files and GNU-style long
// options. One struct holds them all with POV-Ray's defaults; nothing here is global (STYLE.md (b)).
#pragma once

#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "renderer/image/image.hpp"
#include "renderer/render_scene.hpp"

namespace povtrace::app {

// Bad command line or .ini content: main() prints it and exits with status 2.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

enum class LightingModel { povray, textbook };

// +KI +KF +KFI +KFF +KC +SF +EF +STP and +K (Initial_Clock … Frame_Step, Clock): POV-Ray 3.7's animation
// settings as written; app/animation.hpp turns them into the frames to render. Unset values take POV-Ray's
// defaults there (initial frame 1, final frame 1, clocks 0 and 1, step 1).
struct AnimationOptions {
  std::optional<int> initial_frame;           // +KFI / Initial_Frame
  std::optional<int> final_frame;             // +KFF / Final_Frame
  std::optional<double> initial_clock;        // +KI / Initial_Clock
  std::optional<double> final_clock;          // +KF / Final_Clock
  bool cyclic = false;                        // +KC / Cyclic_Animation
  std::optional<double> subset_start;         // +SF / Subset_Start_Frame: a frame number, or a fraction in (0,1)
  std::optional<double> subset_end;           // +EF / Subset_End_Frame
  int frame_step = 1;                         // +STP / Frame_Step
  std::optional<double> clock;                // +K / Clock: the clock of a single (non-animated) render
};

// +SR +ER +SC +EC (Start_Row, End_Row, Start_Column, End_Column) as written: a value in [0,1) (start) or [0,1]
// (end) is a fraction of the image, otherwise a 1-based pixel (POV-Ray 3.7 view.cpp); resolved against the
// image size when the render starts.
struct RegionOptions {
  std::optional<double> start_row, end_row, start_column, end_column;
};

// +G streams (POV-Ray 3.7's text streams): each goes to the console (stderr) and/or a file.
//   debug = #debug text; warning = parser and povtrace warnings; fatal = errors; render and statistics =
//   povtrace's summary lines. +GA / All_Console sets every console flag; All_File receives every stream.
struct MessageStream {
  bool console = true;
  std::optional<std::filesystem::path> file;
};

struct MessageStreams {
  MessageStream debug, fatal, render, statistics, warning;
  std::optional<std::filesystem::path> all_file;  // +GA<file> / All_File
  bool append = false;                            // +GP / Append_File: append to the files instead of replacing
};

// Pre/Post_Scene_Command, Pre/Post_Frame_Command, User_Abort_Command, Fatal_Error_Command and their *_Return
// keys (app/shellouts.hpp runs them, only with --allow-shellout).
struct ShellCommand {
  std::string command;   // empty: none
  char action = 'i';     // *_Return: i ignore, s skip frame, a skip all, q quit, u user abort, f fatal error
  bool negate = false;   // '-' or '!' before the action: act on exit status 0 instead of non-zero
};

struct ShellCommands {
  ShellCommand pre_scene, post_scene, pre_frame, post_frame, user_abort, fatal_error;
};

struct RenderOptions {
  std::filesystem::path input;                  // +I / Input_File_Name / the positional .pov argument
  std::optional<std::filesystem::path> output;  // +O / Output_File_Name; default: input stem + extension, in cwd
  int width = 800;                              // +W / Width   (POV-Ray's Debian povray.ini default)
  int height = 600;                             // +H / Height
  bool antialias = false;                       // +A / -A / Antialias
  double antialias_threshold = 0.3;             // +A0.x / Antialias_Threshold (clipped to 0…1)
  int antialias_depth = 3;                      // +R / Antialias_Depth (clipped to 1…9)
  int sampling_method = 1;                      // +AM1 / +AM2 / Sampling_Method
  bool jitter = true;                           // +J / -J / Jitter (POV-Ray's default is on)
  double jitter_amount = 1.0;                   // +J0.5 / Jitter_Amount (clipped to 0…1)
  double antialias_gamma = 2.5;                 // +AG / Antialias_Gamma
  bool antialias_gamma_srgb = false;            // Antialias_Gamma=sRGB (antialias_gamma is then 2.2)
  bool output_alpha = false;                    // +UA / Output_Alpha
  bool povray_tolerances = false;               // --povray-tolerances: no rescaling of tiny or huge scenes
  // --no-specialise[=NAME,…]: the general paths instead of the specialised ones (same image, slower)
  render::SpecialisationChoice specialise;
  bool expression_programs = true;              // the parser's (--no-specialise=expression-programs turns it off)
  std::vector<std::filesystem::path> library_paths;  // +L / Library_Path, in order
  std::optional<image::FileFormat> format;      // +F<type> / Output_File_Type; else from output extension; else PNG
  int bits_per_channel = 8;                     // +FN16 / +FP16 / Bits_Per_Color (8 or 16; ignored for EXR)
  bool exr_full_float = false;                  // --format=exr32 (POV-Ray's own EXR, +FE, is half float)
  bool grayscale = false;                       // Grayscale_Output / +FNG
  int compression = 0;                          // Compression: JPEG quality (0 and 1 mean 85, as POV-Ray)
  std::optional<double> file_gamma;             // File_Gamma (nullopt: sRGB)
  image::Dither dither = image::Dither::none;   // +TH / Dither, Dither_Method: the method in use, or none
  image::Dither dither_method = image::Dither::floyd_steinberg;  // Dither_Method (POV-Ray's default FS)
  bool write_file = true;                       // +F / -F / Output_To_File: -F renders without writing a file
  int threads = 0;                              // +WT<n> / --threads; 0 = all cores
  std::vector<std::pair<std::string, double>> declares;  // Declare=NAME=VALUE, in order
  bool display = false;                         // +D/-D: accepted, povtrace has no preview window
  bool verbose = false;                         // +V/-V
  bool pause = false;                           // +P/-P: accepted, nothing to pause on
  std::optional<std::filesystem::path> stats_json;  // --stats=FILE.json
  bool vs_povray = false;                       // --vs-povray
  LightingModel lighting = LightingModel::povray;  // --lighting=povray|textbook
  bool help = false;                            // --help / -h
  AnimationOptions animation;
  RegionOptions region;
  bool continue_trace = false;                  // +C / Continue_Trace
  int quality = 9;                              // +Q / Quality: 0-9 (10, 11 clipped to 9 as POV-Ray)
  std::vector<std::pair<std::string, std::string>> string_declares;  // Declare=NAME="text", in order
  std::optional<std::filesystem::path> include_header;  // +HI / Include_Header: read before the scene
  std::optional<double> language_version;       // +MV / Version: the #version the parse starts with
  int warning_level = 9;                        // +WL / Warning_Level: 0-4 silence the parser's warnings
  MessageStreams streams;                       // +GA +GD +GF +GR +GS +GW +GP and the *_Console/*_File keys
  std::optional<std::filesystem::path> create_ini;  // +GI / Create_Ini: write the resolved settings here
  ShellCommands shell_commands;                 // *_Command / *_Return
  // --radiosity-povray-order: radiosity's final pass in POV-Ray's one-thread order too, on one thread (render.hpp
  // RenderSettings::radiosity_povray_order).
  bool radiosity_povray_order = false;
  bool allow_shellout = false;                  // --allow-shellout: run the shell commands
  bool version = false;                         // --version
  enum class Print { nothing, switch_table, man_page };
  Print print = Print::nothing;                 // --switch-table, --man-page (build time): print and exit
  // One line per POV-Ray setting that povtrace accepts but does not act on (each key once), and other notes
  // for the user; main prints them to the warning stream.
  std::vector<std::string> warnings;
};

// Where povray.ini is looked for (POV-Ray 3.7 on unix): $POVINI, ./povray.ini, $HOME/.povray/3.7/povray.ini,
// the system file, $HOME/.povrayrc. Passed in so that tests stay hermetic; main passes the real one.
struct IniEnvironment {
  std::optional<std::string> povini;   // $POVINI
  std::optional<std::string> home;     // $HOME
  std::filesystem::path system_ini = "/etc/povray/3.7/povray.ini";
  std::filesystem::path working_directory = ".";
};

// The process's own environment ($POVINI, $HOME).
IniEnvironment process_environment();

// Parses argv (argv[0] is skipped). `.ini` arguments (also `file.ini[Section]`) are read in place, in order,
// relative to the current directory; `Key=Value` arguments are .ini settings, as in POV-Ray; `--` ends the
// options. A missing scene is not an error here (main decides). Throws UsageError naming the offending option.
// With `environment`, the first povray.ini found (see IniEnvironment) is read before the arguments, unless an
// argument is --no-povray-ini; without it (tests) none is read.
RenderOptions parse_command_line(int argc, const char* const* argv, const IniEnvironment* environment = nullptr);

// The povray.ini that `environment` selects, if any exists.
std::optional<std::filesystem::path> find_povray_ini(const IniEnvironment& environment);

// Applies one .ini file's keys to `options` (POV-Ray's INI syntax: Key=Value, ';' comments, [sections] ignored
// except that only the unnamed/first section is read, as POV-Ray does without a section selector).
void apply_ini_file(const std::filesystem::path& ini, RenderOptions& options);

// Applies the keys before the first section header plus those of every section named `section`
// (case-insensitive), as POV-Ray does for the argument `file.ini[section]`. A section that is absent is a
// UsageError (POV-Ray ignores it silently; a typo there would change a render without warning).
void apply_ini_section(const std::filesystem::path& ini, const std::string& section, RenderOptions& options);

// Applies one switch such as "+W320", "-A", "+A0.3" or "Declare=N=1" (the INI form). Throws UsageError.
void apply_switch(const std::string& text, RenderOptions& options);

// The output path and format the options resolve to (POV-Ray's rules: +F type, else the output extension,
// else PNG; default name = input stem + ".png"/".exr"/".ppm" in the working directory).
std::filesystem::path resolved_output_path(const RenderOptions& options);
image::EncodeOptions resolved_encoding(const RenderOptions& options);

// The text printed by --help.
std::string usage_text();

// The text printed by --version.
std::string version_text();

// Every POV-Ray 3.7 switch and INI key with what povtrace does with it, one Markdown table row each
// (docs/switches.md, the man page).
std::string switch_table_markdown();

// The man page (roff), generated from the same table at build time.
std::string man_page();

// The resolved settings as an INI file (+GI / Create_Ini) that reads back to the same options.
std::string ini_text(const RenderOptions& options);

}  // namespace povtrace::app
