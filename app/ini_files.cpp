// POV-Ray INI files: reading (sections, nested files, Include_Ini), the povray.ini search, and writing the
// resolved settings back as an INI file (+GI / Create_Ini).

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "app/option_table.hpp"

namespace povtrace::app {
namespace detail {
namespace {

namespace fs = std::filesystem;

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
    if (!apply_ini_key(key, unquote(trim(line.substr(eq + 1))), where + ": " + std::string(key), o, depth)) {
      throw UsageError(where + ": unknown key " + in_quotes(key));
    }
  } else if (const std::optional<IniReference> nested = as_ini_reference(unquote(line))) {
    if (depth >= kMaxIniNesting) throw UsageError(where + ": .ini files nested too deeply");
    apply_ini(nested->path, nested->section, o, depth + 1);
  } else {
    throw UsageError(where + ": expected Key=Value, got " + in_quotes(line));
  }
}

}  // namespace

// "scene.ini" or "scene.ini[Section]" (any case of ".ini").
std::optional<IniReference> as_ini_reference(string_view arg) {
  if (iends_with(arg, ".ini")) return IniReference{fs::path(arg), std::nullopt};
  const size_t open = arg.rfind('[');
  if (arg.ends_with(']') && open != string_view::npos && iends_with(arg.substr(0, open), ".ini")) {
    return IniReference{fs::path(arg.substr(0, open)), std::string(arg.substr(open + 1, arg.size() - open - 2))};
  }
  return std::nullopt;
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

}  // namespace detail

// ---- povray.ini --------------------------------------------------------------------------------------------

IniEnvironment process_environment() {
  IniEnvironment e;
  if (const char* povini = std::getenv("POVINI")) e.povini = povini;
  if (const char* home = std::getenv("HOME"); home != nullptr && *home != '\0') e.home = home;
  return e;
}

// POV-Ray 3.7's unix order (vfe/unix/unixoptions.cpp, Process_povray_ini): $POVINI, ./povray.ini,
// ~/.povray/3.7/povray.ini, the system povray.ini, ~/.povrayrc. The first that exists is read; POV-Ray warns
// when $POVINI names a missing file and goes on with the others, and so does povtrace (in the caller).
std::optional<std::filesystem::path> find_povray_ini(const IniEnvironment& e) {
  namespace fs = std::filesystem;
  std::vector<fs::path> candidates;
  if (e.povini) candidates.emplace_back(*e.povini);
  candidates.push_back(e.working_directory / "povray.ini");
  if (e.home) candidates.push_back(fs::path(*e.home) / ".povray" / "3.7" / "povray.ini");
  candidates.push_back(e.system_ini);
  if (e.home) candidates.push_back(fs::path(*e.home) / ".povrayrc");
  for (const fs::path& p : candidates) {
    std::error_code error;
    if (fs::is_regular_file(p, error)) return p;
  }
  return std::nullopt;
}

// ---- Create_Ini -------------------------------------------------------------------------------------------

namespace {

std::string number(double x) {
  char text[40];
  std::snprintf(text, sizeof text, "%.17g", x);
  return text;
}

std::string on_off(bool b) { return b ? "On" : "Off"; }

std::string quoted(const std::filesystem::path& p) { return "\"" + p.string() + "\""; }

char format_letter(image::FileFormat f) {
  switch (f) {
    case image::FileFormat::png: return 'N';
    case image::FileFormat::exr: return 'E';
    case image::FileFormat::ppm: return 'P';
    case image::FileFormat::tga: return 'T';
    case image::FileFormat::tga_rle: return 'C';
    case image::FileFormat::jpeg: return 'J';
    case image::FileFormat::bmp: return 'B';
    case image::FileFormat::hdr: return 'H';
  }
  return 'N';
}

const char* dither_name(image::Dither d) {
  switch (d) {
    case image::Dither::bayer2: return "B2";
    case image::Dither::bayer3: return "B3";
    case image::Dither::bayer4: return "B4";
    case image::Dither::diffusion1d: return "D1";
    case image::Dither::diffusion2d: return "D2";
    default: return "FS";
  }
}

void write_stream(std::ostream& out, const char* name, const MessageStream& s) {
  out << name << "_Console=" << on_off(s.console) << "\n";
  if (s.file) out << name << "_File=" << quoted(*s.file) << "\n";
}

void write_command(std::ostream& out, const char* name, const ShellCommand& c) {
  if (c.command.empty()) return;
  out << name << "_Command=" << c.command << "\n";
  out << name << "_Return=" << (c.negate ? "!" : "") << c.action << "\n";
}

}  // namespace

// Every setting POV-Ray has a key for, so that reading the file gives the same RenderOptions; povtrace's own
// long options (--format=exr32, --stats, --lighting, …) have no INI key and are not written.
std::string ini_text(const RenderOptions& o) {
  std::ostringstream out;
  out << "; written by povtrace (Create_Ini); reads back to the same settings\n";
  if (!o.input.empty()) out << "Input_File_Name=" << quoted(o.input) << "\n";
  if (o.include_header) out << "Include_Header=" << quoted(*o.include_header) << "\n";
  for (const auto& l : o.library_paths) out << "Library_Path=" << quoted(l) << "\n";
  if (o.language_version) out << "Version=" << number(*o.language_version) << "\n";
  for (const auto& [name, value] : o.declares) out << "Declare=" << name << "=" << number(value) << "\n";
  for (const auto& [name, value] : o.string_declares) out << "Declare=" << name << "=\"" << value << "\"\n";
  if (o.output) out << "Output_File_Name=" << quoted(*o.output) << "\n";
  out << "Width=" << o.width << "\nHeight=" << o.height << "\n";
  if (o.format) out << "Output_File_Type=" << format_letter(*o.format) << "\n";
  out << "Bits_Per_Color=" << o.bits_per_channel << "\nGrayscale_Output=" << on_off(o.grayscale)
      << "\nCompression=" << o.compression << "\nOutput_To_File=" << on_off(o.write_file)
      << "\nOutput_Alpha=" << on_off(o.output_alpha) << "\n";
  out << "File_Gamma=" << (o.file_gamma ? number(*o.file_gamma) : "sRGB") << "\n";
  out << "Dither_Method=" << dither_name(o.dither_method) << "\nDither=" << on_off(o.dither != image::Dither::none)
      << "\n";
  out << "Antialias=" << on_off(o.antialias) << "\nAntialias_Threshold=" << number(o.antialias_threshold)
      << "\nAntialias_Depth=" << o.antialias_depth << "\nSampling_Method=" << o.sampling_method
      << "\nAntialias_Gamma=" << (o.antialias_gamma_srgb ? "sRGB" : number(o.antialias_gamma))
      << "\nJitter=" << on_off(o.jitter) << "\nJitter_Amount=" << number(o.jitter_amount) << "\n";
  const AnimationOptions& a = o.animation;
  if (a.clock) out << "Clock=" << number(*a.clock) << "\n";
  if (a.initial_clock) out << "Initial_Clock=" << number(*a.initial_clock) << "\n";
  if (a.final_clock) out << "Final_Clock=" << number(*a.final_clock) << "\n";
  if (a.initial_frame) out << "Initial_Frame=" << *a.initial_frame << "\n";
  if (a.final_frame) out << "Final_Frame=" << *a.final_frame << "\n";
  out << "Cyclic_Animation=" << on_off(a.cyclic) << "\nFrame_Step=" << a.frame_step << "\n";
  if (a.subset_start) out << "Subset_Start_Frame=" << number(*a.subset_start) << "\n";
  if (a.subset_end) out << "Subset_End_Frame=" << number(*a.subset_end) << "\n";
  const RegionOptions& r = o.region;
  if (r.start_row) out << "Start_Row=" << number(*r.start_row) << "\n";
  if (r.end_row) out << "End_Row=" << number(*r.end_row) << "\n";
  if (r.start_column) out << "Start_Column=" << number(*r.start_column) << "\n";
  if (r.end_column) out << "End_Column=" << number(*r.end_column) << "\n";
  out << "Continue_Trace=" << on_off(o.continue_trace) << "\nQuality=" << o.quality << "\n";
  out << "Work_Threads=" << o.threads << "\nDisplay=" << on_off(o.display) << "\nVerbose=" << on_off(o.verbose)
      << "\nPause_When_Done=" << on_off(o.pause) << "\nWarning_Level=" << o.warning_level << "\n";
  write_stream(out, "Debug", o.streams.debug);
  write_stream(out, "Fatal", o.streams.fatal);
  write_stream(out, "Render", o.streams.render);
  write_stream(out, "Statistic", o.streams.statistics);
  write_stream(out, "Warning", o.streams.warning);
  if (o.streams.all_file) out << "All_File=" << quoted(*o.streams.all_file) << "\n";
  out << "Append_File=" << on_off(o.streams.append) << "\n";
  write_command(out, "Pre_Scene", o.shell_commands.pre_scene);
  write_command(out, "Post_Scene", o.shell_commands.post_scene);
  write_command(out, "Pre_Frame", o.shell_commands.pre_frame);
  write_command(out, "Post_Frame", o.shell_commands.post_frame);
  write_command(out, "User_Abort", o.shell_commands.user_abort);
  write_command(out, "Fatal_Error", o.shell_commands.fatal_error);
  return out.str();
}

}  // namespace povtrace::app
