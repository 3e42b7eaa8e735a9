// Tests of povtrace's option parsing: POV-Ray switches, long options, .ini files, error messages and the
// output name and encoding the options resolve to. Each table row states the whole expected RenderOptions as
// "the defaults plus these changes", and the comparison covers every field, so a switch that also changes
// something it should not is caught too.

#include "app/options.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

namespace povtrace::app {
namespace {

namespace fs = std::filesystem;
using image::FileFormat;

// ---- Helpers --------------------------------------------------------------------------------------

std::string format_name(const std::optional<FileFormat>& f) {
  if (!f) return "none";
  switch (*f) {
    case FileFormat::png: return "png";
    case FileFormat::exr: return "exr";
    case FileFormat::ppm: return "ppm";
    case FileFormat::tga: return "tga";
    case FileFormat::tga_rle: return "tga_rle";
    case FileFormat::jpeg: return "jpeg";
    case FileFormat::bmp: return "bmp";
    case FileFormat::hdr: return "hdr";
  }
  return "?";
}

// Every field, one per line, so a failed comparison shows which one differs.
std::string dump(const RenderOptions& o) {
  std::ostringstream s;
  s << std::setprecision(17);
  s << "input " << o.input << "\noutput " << (o.output ? o.output->string() : "none") << "\nsize " << o.width
    << "x" << o.height << "\nantialias " << o.antialias << " threshold " << o.antialias_threshold << " depth "
    << o.antialias_depth << " method " << o.sampling_method << " gamma " << o.antialias_gamma << "\njitter "
    << o.jitter << " amount " << o.jitter_amount << "\nalpha " << o.output_alpha << "\nlibrary";
  for (const fs::path& p : o.library_paths) s << " " << p;
  s << "\nformat " << format_name(o.format) << " bits " << o.bits_per_channel << " full_float " << o.exr_full_float
    << " write_file " << o.write_file << "\nthreads " << o.threads << "\ndeclares";
  for (const auto& [name, value] : o.declares) s << " " << name << "=" << value;
  s << "\ndisplay " << o.display << " verbose " << o.verbose << " pause " << o.pause << "\nstats "
    << (o.stats_json ? o.stats_json->string() : "none") << "\nvs_povray " << o.vs_povray << " lighting "
    << (o.lighting == LightingModel::povray ? "povray" : "textbook") << "\npovray_tolerances " << o.povray_tolerances
    << " specialise " << o.specialise.nearest_shadow_first << o.specialise.no_shadow_rays << o.specialise.embree_meshes
    << " expression_programs " << o.expression_programs
    << "\nhelp " << o.help << "\n";
  return s.str();
}

RenderOptions parse(const std::vector<std::string>& args) {
  std::vector<const char*> argv{"povtrace"};
  for (const std::string& a : args) argv.push_back(a.c_str());
  return parse_command_line(static_cast<int>(argv.size()), argv.data());
}

std::string joined(const std::vector<std::string>& args) {
  std::string text;
  for (const std::string& a : args) text += (text.empty() ? "" : " ") + a;
  return text;
}

// The message of the UsageError that parsing `args` throws, or "" when it throws none.
std::string usage_error(const std::vector<std::string>& args) {
  try {
    parse(args);
  } catch (const UsageError& e) {
    return e.what();
  }
  return "";
}

using Change = std::function<void(RenderOptions&)>;

struct ParseCase {
  std::vector<std::string> args;
  Change expected;  // applied to default RenderOptions
};

void PrintTo(const ParseCase& c, std::ostream* out) { *out << "[" << joined(c.args) << "]"; }

void expect_parses_to(const std::vector<std::string>& args, const Change& change) {
  RenderOptions expected;
  change(expected);
  EXPECT_EQ(dump(parse(args)), dump(expected)) << "arguments: " << joined(args);
}

// A temporary folder, made the working directory for the test, removed afterwards.
class TempDir : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string name = std::string(info->test_suite_name()) + "_" + info->name();
    std::replace(name.begin(), name.end(), '/', '_');  // parameterised tests are named Suite/Test/N
    dir_ = fs::temp_directory_path() / ("povtrace_options_" + name + "_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    old_cwd_ = fs::current_path();
    fs::current_path(dir_);
  }
  void TearDown() override {
    fs::current_path(old_cwd_);
    fs::remove_all(dir_);
  }
  static void write(const fs::path& path, const std::string& text) {
    if (path.has_parent_path()) fs::create_directories(path.parent_path());
    std::ofstream(path, std::ios::binary) << text;
  }
  fs::path dir_;
  fs::path old_cwd_;
};

// ---- Switches and long options: each sets exactly the right fields --------------------------------

class ParsesTo : public ::testing::TestWithParam<ParseCase> {};

TEST_P(ParsesTo, ExactOptions) { expect_parses_to(GetParam().args, GetParam().expected); }

INSTANTIATE_TEST_SUITE_P(Input, ParsesTo, ::testing::Values(
    ParseCase{{}, [](RenderOptions&) {}},
    ParseCase{{"scene.pov"}, [](RenderOptions& o) { o.input = "scene.pov"; }},
    ParseCase{{"+Iscene.pov"}, [](RenderOptions& o) { o.input = "scene.pov"; }},
    ParseCase{{"-iScene.POV"}, [](RenderOptions& o) { o.input = "Scene.POV"; }},
    ParseCase{{"--input=a.pov"}, [](RenderOptions& o) { o.input = "a.pov"; }},
    ParseCase{{"--input", "a.pov"}, [](RenderOptions& o) { o.input = "a.pov"; }},
    ParseCase{{"Input_File_Name=a.pov"}, [](RenderOptions& o) { o.input = "a.pov"; }},
    ParseCase{{"+Ia.pov", "b.pov"}, [](RenderOptions& o) { o.input = "b.pov"; }},
    ParseCase{{"--", "-odd.pov"}, [](RenderOptions& o) { o.input = "-odd.pov"; }},
    ParseCase{{"+Oout.png"}, [](RenderOptions& o) { o.output = "out.png"; }},
    ParseCase{{"-oout.png"}, [](RenderOptions& o) { o.output = "out.png"; }},
    ParseCase{{"-o", "out.png"}, [](RenderOptions& o) { o.output = "out.png"; }},
    ParseCase{{"--output=dir/"}, [](RenderOptions& o) { o.output = "dir/"; }},
    ParseCase{{"--output", "x.exr"}, [](RenderOptions& o) { o.output = "x.exr"; }},
    ParseCase{{"Output_File_Name=q.png"}, [](RenderOptions& o) { o.output = "q.png"; }}));

INSTANTIATE_TEST_SUITE_P(Size, ParsesTo, ::testing::Values(
    ParseCase{{"+W320"}, [](RenderOptions& o) { o.width = 320; }},
    ParseCase{{"-W320"}, [](RenderOptions& o) { o.width = 320; }},
    ParseCase{{"+w320", "+h240"}, [](RenderOptions& o) { o.width = 320, o.height = 240; }},
    ParseCase{{"+H1"}, [](RenderOptions& o) { o.height = 1; }},
    ParseCase{{"+W65536", "+H4096"}, [](RenderOptions& o) { o.width = 65536, o.height = 4096; }},
    ParseCase{{"--width=640", "--height", "480"}, [](RenderOptions& o) { o.width = 640, o.height = 480; }},
    ParseCase{{"Width=16", "height=12"}, [](RenderOptions& o) { o.width = 16, o.height = 12; }},
    ParseCase{{"+W100", "--width=200", "+W300"}, [](RenderOptions& o) { o.width = 300; }}));

INSTANTIATE_TEST_SUITE_P(Antialias, ParsesTo, ::testing::Values(
    ParseCase{{"+A"}, [](RenderOptions& o) { o.antialias = true; }},
    ParseCase{{"+a"}, [](RenderOptions& o) { o.antialias = true; }},
    ParseCase{{"+A0.5"}, [](RenderOptions& o) { o.antialias = true, o.antialias_threshold = 0.5; }},
    ParseCase{{"+A.25"}, [](RenderOptions& o) { o.antialias = true, o.antialias_threshold = 0.25; }},
    ParseCase{{"+A1.7"}, [](RenderOptions& o) { o.antialias = true, o.antialias_threshold = 1.0; }},
    ParseCase{{"+A-0.5"}, [](RenderOptions& o) { o.antialias = true, o.antialias_threshold = 0.0; }},
    ParseCase{{"+A", "-A"}, [](RenderOptions&) {}},
    ParseCase{{"-A0.1"}, [](RenderOptions& o) { o.antialias_threshold = 0.1; }},
    ParseCase{{"-A0.1", "+A"}, [](RenderOptions& o) { o.antialias = true, o.antialias_threshold = 0.1; }},
    ParseCase{{"--antialias"}, [](RenderOptions& o) { o.antialias = true; }},
    ParseCase{{"--antialias=0.2"}, [](RenderOptions& o) { o.antialias = true, o.antialias_threshold = 0.2; }},
    ParseCase{{"+A", "--no-antialias"}, [](RenderOptions&) {}},
    ParseCase{{"+AM2"}, [](RenderOptions& o) { o.sampling_method = 2; }},
    ParseCase{{"-am2"}, [](RenderOptions& o) { o.sampling_method = 2; }},
    ParseCase{{"+AM2", "+AM1"}, [](RenderOptions& o) { o.sampling_method = 1; }},
    ParseCase{{"--sampling-method=2"}, [](RenderOptions& o) { o.sampling_method = 2; }},
    ParseCase{{"+AG1.8"}, [](RenderOptions& o) { o.antialias_gamma = 1.8; }},
    ParseCase{{"+ag1"}, [](RenderOptions& o) { o.antialias_gamma = 1.0; }},
    ParseCase{{"+R5"}, [](RenderOptions& o) { o.antialias_depth = 5; }},
    ParseCase{{"+r12"}, [](RenderOptions& o) { o.antialias_depth = 9; }},
    ParseCase{{"+R0"}, [](RenderOptions& o) { o.antialias_depth = 1; }},
    ParseCase{{"-R-3"}, [](RenderOptions& o) { o.antialias_depth = 1; }},
    ParseCase{{"--aa-depth=4"}, [](RenderOptions& o) { o.antialias_depth = 4; }},
    ParseCase{{"--aa-depth", "20"}, [](RenderOptions& o) { o.antialias_depth = 9; }}));

INSTANTIATE_TEST_SUITE_P(Jitter, ParsesTo, ::testing::Values(
    ParseCase{{"-J"}, [](RenderOptions& o) { o.jitter = false; }},
    ParseCase{{"-j", "+J"}, [](RenderOptions&) {}},
    ParseCase{{"+J0.5"}, [](RenderOptions& o) { o.jitter_amount = 0.5; }},
    ParseCase{{"-J0.5"}, [](RenderOptions& o) { o.jitter = false, o.jitter_amount = 0.5; }},
    ParseCase{{"+J1.5"}, [](RenderOptions& o) { o.jitter_amount = 1.0; }},
    ParseCase{{"+J-1"}, [](RenderOptions& o) { o.jitter_amount = 0.0; }},
    ParseCase{{"--no-jitter"}, [](RenderOptions& o) { o.jitter = false; }},
    ParseCase{{"--no-jitter", "--jitter"}, [](RenderOptions&) {}},
    ParseCase{{"--jitter=0.25"}, [](RenderOptions& o) { o.jitter_amount = 0.25; }}));

INSTANTIATE_TEST_SUITE_P(Library, ParsesTo, ::testing::Values(
    ParseCase{{"+Lone", "-ltwo"}, [](RenderOptions& o) { o.library_paths = {"one", "two"}; }},
    ParseCase{{"--library-path=a", "--library-path", "b", "Library_Path=c", "+L/d"},
              [](RenderOptions& o) { o.library_paths = {"a", "b", "c", "/d"}; }}));

INSTANTIATE_TEST_SUITE_P(FileType, ParsesTo, ::testing::Values(
    ParseCase{{"+FN"}, [](RenderOptions& o) { o.format = FileFormat::png; }},
    ParseCase{{"+fn"}, [](RenderOptions& o) { o.format = FileFormat::png; }},
    ParseCase{{"+FN16"}, [](RenderOptions& o) { o.format = FileFormat::png, o.bits_per_channel = 16; }},
    ParseCase{{"+FN16", "+FN8"}, [](RenderOptions& o) { o.format = FileFormat::png; }},
    ParseCase{{"+FN16", "+FN"}, [](RenderOptions& o) { o.format = FileFormat::png, o.bits_per_channel = 16; }},
    ParseCase{{"+FN16", "+FP"}, [](RenderOptions& o) { o.format = FileFormat::ppm, o.bits_per_channel = 16; }},
    ParseCase{{"+FE"}, [](RenderOptions& o) { o.format = FileFormat::exr; }},
    // As povray, the bits after +FE set Bits_Per_Color (EXR ignores them).
    ParseCase{{"+fe16"}, [](RenderOptions& o) { o.format = FileFormat::exr, o.bits_per_channel = 16; }},
    ParseCase{{"+FP"}, [](RenderOptions& o) { o.format = FileFormat::ppm; }},
    ParseCase{{"+FP16"}, [](RenderOptions& o) { o.format = FileFormat::ppm, o.bits_per_channel = 16; }},
    ParseCase{{"-F"}, [](RenderOptions& o) { o.write_file = false; }},
    ParseCase{{"-FN"}, [](RenderOptions& o) { o.write_file = false, o.format = FileFormat::png; }},
    ParseCase{{"-F", "+F"}, [](RenderOptions&) {}},
    ParseCase{{"--format=png16"}, [](RenderOptions& o) { o.format = FileFormat::png, o.bits_per_channel = 16; }},
    ParseCase{{"+FN16", "--format=png"}, [](RenderOptions& o) { o.format = FileFormat::png; }},
    ParseCase{{"--format", "exr"}, [](RenderOptions& o) { o.format = FileFormat::exr; }},
    ParseCase{{"--format=exr32"}, [](RenderOptions& o) { o.format = FileFormat::exr, o.exr_full_float = true; }},
    ParseCase{{"--format=exr32", "+FE"}, [](RenderOptions& o) { o.format = FileFormat::exr; }},
    ParseCase{{"--format=ppm"}, [](RenderOptions& o) { o.format = FileFormat::ppm; }},
    ParseCase{{"--format=ppm16"}, [](RenderOptions& o) { o.format = FileFormat::ppm, o.bits_per_channel = 16; }},
    ParseCase{{"+UA"}, [](RenderOptions& o) { o.output_alpha = true; }},
    ParseCase{{"+ua", "-UA"}, [](RenderOptions&) {}},
    ParseCase{{"--alpha"}, [](RenderOptions& o) { o.output_alpha = true; }}));

INSTANTIATE_TEST_SUITE_P(Misc, ParsesTo, ::testing::Values(
    ParseCase{{"+WT4"}, [](RenderOptions& o) { o.threads = 4; }},
    ParseCase{{"+wt0"}, [](RenderOptions& o) { o.threads = 0; }},
    ParseCase{{"--threads=2", "--threads", "3"}, [](RenderOptions& o) { o.threads = 3; }},
    ParseCase{{"Work_Threads=5"}, [](RenderOptions& o) { o.threads = 5; }},
    ParseCase{{"+D"}, [](RenderOptions& o) { o.display = true; }},
    ParseCase{{"+D", "-D0"}, [](RenderOptions&) {}},
    ParseCase{{"+DG"}, [](RenderOptions& o) { o.display = true; }},
    ParseCase{{"+V"}, [](RenderOptions& o) { o.verbose = true; }},
    ParseCase{{"+v", "-V"}, [](RenderOptions&) {}},
    ParseCase{{"--verbose"}, [](RenderOptions& o) { o.verbose = true; }},
    ParseCase{{"+P"}, [](RenderOptions& o) { o.pause = true; }},
    ParseCase{{"+P", "-p"}, [](RenderOptions&) {}},
    ParseCase{{"--stats=s.json"}, [](RenderOptions& o) { o.stats_json = "s.json"; }},
    ParseCase{{"--stats", "t.json"}, [](RenderOptions& o) { o.stats_json = "t.json"; }},
    ParseCase{{"--vs-povray"}, [](RenderOptions& o) { o.vs_povray = true; }},
    ParseCase{{"--lighting=textbook"}, [](RenderOptions& o) { o.lighting = LightingModel::textbook; }},
    ParseCase{{"--no-specialise"}, [](RenderOptions& o) {
                o.specialise = render::SpecialisationChoice{false, false, false};
                o.expression_programs = false;
              }},
    ParseCase{{"--no-specialise=expression-programs"}, [](RenderOptions& o) { o.expression_programs = false; }},
    ParseCase{{"--no-specialise=no-shadow-rays,nearest-shadow-first"},
              [](RenderOptions& o) { o.specialise.nearest_shadow_first = o.specialise.no_shadow_rays = false; }},
    ParseCase{{"--no-specialise=no-shadow-rays"}, [](RenderOptions& o) { o.specialise.no_shadow_rays = false; }},
    ParseCase{{"--povray-tolerances"}, [](RenderOptions& o) { o.povray_tolerances = true; }},
    ParseCase{{"--lighting", "textbook", "--lighting=povray"}, [](RenderOptions&) {}},
    ParseCase{{"--help"}, [](RenderOptions& o) { o.help = true; }},
    ParseCase{{"-h"}, [](RenderOptions& o) { o.help = true; }},
    ParseCase{{"Verbose=on", "Display=yes", "Pause_When_Done=true"},
              [](RenderOptions& o) { o.verbose = o.display = o.pause = true; }}));

INSTANTIATE_TEST_SUITE_P(Declare, ParsesTo, ::testing::Values(
    ParseCase{{"Declare=N=2.5"}, [](RenderOptions& o) { o.declares = {{"N", 2.5}}; }},
    ParseCase{{"declare=Clock_2=1e2"}, [](RenderOptions& o) { o.declares = {{"Clock_2", 100.0}}; }},
    ParseCase{{"DECLARE=_x=-3"}, [](RenderOptions& o) { o.declares = {{"_x", -3.0}}; }},
    ParseCase{{"--declare", "A=1", "--declare=B=-0.5", "Declare=A=2"},
              [](RenderOptions& o) { o.declares = {{"A", 1.0}, {"B", -0.5}, {"A", 2.0}}; }}));

INSTANTIATE_TEST_SUITE_P(Everything, ParsesTo, ::testing::Values(
    // The regression tests' and benchmark's command lines.
    ParseCase{{"-D", "-A", "+W320", "+H240", "+FE", "+O/tmp/x.exr", "scene.pov"},
              [](RenderOptions& o) {
                o.width = 320, o.height = 240, o.format = FileFormat::exr, o.output = "/tmp/x.exr";
                o.input = "scene.pov";
              }},
    ParseCase{{"-D", "-A", "+W64", "+H48", "+FE", "+WT2", "+Oi.exr", "--stats=s.json", "g.pov"},
              [](RenderOptions& o) {
                o.width = 64, o.height = 48, o.format = FileFormat::exr, o.threads = 2, o.output = "i.exr";
                o.stats_json = "s.json", o.input = "g.pov";
              }}));

// ---- Errors: a UsageError whose message names the offending option ------------------------------

struct ErrorCase {
  std::vector<std::string> args;
  std::vector<std::string> message_parts;  // each must appear in the message
};

void PrintTo(const ErrorCase& c, std::ostream* out) { *out << "[" << joined(c.args) << "]"; }

class Rejects : public ::testing::TestWithParam<ErrorCase> {};

TEST_P(Rejects, WithMessageNamingTheOption) {
  const std::string message = usage_error(GetParam().args);
  ASSERT_FALSE(message.empty()) << "no UsageError for " << joined(GetParam().args);
  for (const std::string& part : GetParam().message_parts) EXPECT_NE(message.find(part), std::string::npos) << message;
}

INSTANTIATE_TEST_SUITE_P(Numbers, Rejects, ::testing::Values(
    ErrorCase{{"+Wabc"}, {"+Wabc:", "'abc'"}},
    ErrorCase{{"+W0"}, {"+W0:", "from 1 to 65536"}},
    ErrorCase{{"+W-5"}, {"+W-5:"}},
    ErrorCase{{"+W65537"}, {"+W65537:"}},
    ErrorCase{{"+W32abc"}, {"+W32abc:"}},
    ErrorCase{{"+W32.7"}, {"+W32.7:"}},
    ErrorCase{{"+W 32"}, {"+W 32:"}},
    ErrorCase{{"+W"}, {"+W:"}},
    ErrorCase{{"+H99999999999999999999"}, {"+H99999999999999999999:"}},
    ErrorCase{{"+W65536", "+H4097"}, {"+H4097:", "2^28"}},
    ErrorCase{{"--width=abc"}, {"--width=abc:", "'abc'"}},
    ErrorCase{{"--height", "0"}, {"--height:", "'0'"}},
    ErrorCase{{"--width"}, {"--width", "needs a value"}},
    ErrorCase{{"Width=abc"}, {"Width=abc:"}},
    ErrorCase{{"+Aabc"}, {"+Aabc:"}},
    ErrorCase{{"+Anan"}, {"+Anan:"}},
    ErrorCase{{"+Ainf"}, {"+Ainf:"}},
    ErrorCase{{"+A0.3x"}, {"+A0.3x:"}},
    ErrorCase{{"+J1/2"}, {"+J1/2:"}},
    ErrorCase{{"+AM3"}, {"+AM3:", "from 1 to 2"}},
    ErrorCase{{"+AM0"}, {"+AM0:"}},
    ErrorCase{{"+AM"}, {"+AM:"}},
    ErrorCase{{"+AG0"}, {"+AG0:"}},
    ErrorCase{{"+AG-1"}, {"+AG-1:"}},
    ErrorCase{{"+Rx"}, {"+Rx:"}},
    ErrorCase{{"+R2.5"}, {"+R2.5:"}},
    ErrorCase{{"+WT-1"}, {"+WT-1:"}},
    ErrorCase{{"+WTx"}, {"+WTx:"}},
    ErrorCase{{"--threads=many"}, {"--threads=many:"}},
    ErrorCase{{"--antialias="}, {"--antialias=:"}},
    ErrorCase{{"--antialias=high"}, {"--antialias=high:"}},
    ErrorCase{{"--jitter=x"}, {"--jitter=x:"}}));

INSTANTIATE_TEST_SUITE_P(Unknown, Rejects, ::testing::Values(
    ErrorCase{{"+Z9"}, {"unknown option '+Z9'"}},
    ErrorCase{{"-MX3.7"}, {"unknown option '-MX3.7'"}},
    ErrorCase{{"--xyz"}, {"unknown option '--xyz'"}},
    ErrorCase{{"--xyz=3"}, {"unknown option '--xyz=3'"}},
    ErrorCase{{"--Width=3"}, {"unknown option '--Width=3'"}},
    ErrorCase{{"-"}, {"unknown option '-'"}},
    ErrorCase{{"+"}, {"unknown option '+'"}},
    ErrorCase{{"+Vx"}, {"unknown option '+Vx'"}},
    ErrorCase{{"+UA1"}, {"unknown option '+UA1'"}},
    ErrorCase{{"-Pause"}, {"unknown option '-Pause'"}},
    ErrorCase{{"+D=1"}, {"unknown option '+D=1'"}},
    ErrorCase{{"Foo=1"}, {"unknown option 'Foo=1'"}},
    ErrorCase{{"+Declare=N=1"}, {"+Declare=N=1:", "without a sign"}},
    ErrorCase{{"--alpha=1"}, {"--alpha=1:", "takes no value"}},
    ErrorCase{{"--help=x"}, {"--help=x:"}}));

INSTANTIATE_TEST_SUITE_P(Values, Rejects, ::testing::Values(
    ErrorCase{{"a.pov", "b.pov"}, {"more than one scene", "'a.pov'", "'b.pov'"}},
    ErrorCase{{"+I"}, {"+I:", "missing"}},
    ErrorCase{{"+O"}, {"+O:", "missing"}},
    ErrorCase{{"-L"}, {"-L:", "missing"}},
    ErrorCase{{"-o"}, {"-o:", "needs a value"}},
    ErrorCase{{"--output"}, {"--output", "needs a value"}},
    ErrorCase{{"--stats="}, {"--stats=:", "missing"}},
    ErrorCase{{"+FX"}, {"+FX:", "'X'"}},
    ErrorCase{{"+FTx"}, {"+FTx:"}},
    ErrorCase{{"+FJg"}, {"+FJg:", "PNG and PPM only"}},
    ErrorCase{{"+FN1x"}, {"+FN1x:"}},
    ErrorCase{{"+FN16x"}, {"+FN16x:"}},
    ErrorCase{{"+FEx"}, {"+FEx:"}},
    ErrorCase{{"--format=tga"}, {"--format=tga:", "'tga'"}},
    ErrorCase{{"--format=PNG24"}, {"--format=PNG24:"}},
    ErrorCase{{"--lighting=pbr"}, {"--lighting=pbr:", "'pbr'"}},
    ErrorCase{{"--no-specialise=no-shadow-rays,bogus"},
              {"--no-specialise=no-shadow-rays,bogus:", "'bogus'", "nearest-shadow-first"}},
    ErrorCase{{"Declare=N=abc"}, {"Declare=N=abc:", "'abc'"}},
    ErrorCase{{"Declare=N="}, {"Declare=N=:", "number"}},
    ErrorCase{{"Declare=9N=1"}, {"Declare=9N=1:", "'9N'", "identifier"}},
    ErrorCase{{"Declare=N-1=1"}, {"Declare=N-1=1:"}},
    ErrorCase{{"Declare=N"}, {"Declare=N:", "NAME=VALUE"}},
    ErrorCase{{"--declare", "N=x"}, {"--declare:", "'x'"}},
    ErrorCase{{"--declare=N"}, {"--declare=N:"}},
    ErrorCase{{"Antialias=maybe"}, {"Antialias=maybe:", "'maybe'"}},
    ErrorCase{{"missing.ini"}, {"'missing.ini'"}},
    ErrorCase{{"missing.ini[Sec]"}, {"'missing.ini'"}}));

// ---- .ini files ---------------------------------------------------------------------------------

class IniFile : public TempDir {};

TEST_F(IniFile, EveryKeySetsItsField) {
  write("all.ini",
        "Input_File_Name=scenes/a.pov\n"
        "Output_File_Name=out/a.exr\n"
        "Width=320\nHeight=240\n"
        "Antialias=on\nAntialias_Threshold=0.2\nAntialias_Depth=4\nAntialias_Gamma=1.5\n"
        "Sampling_Method=2\nJitter=off\nJitter_Amount=0.5\n"
        "Library_Path=inc1\nLibrary_Path=inc2\n"
        "Output_File_Type=N16\nOutput_Alpha=true\nDeclare=Size=3.5\n"
        "Display=off\nVerbose=yes\nPause_When_Done=1\nWork_Threads=6\n");
  expect_parses_to({"all.ini"}, [](RenderOptions& o) {
    o.input = "scenes/a.pov", o.output = "out/a.exr", o.width = 320, o.height = 240;
    o.antialias = true, o.antialias_threshold = 0.2, o.antialias_depth = 4, o.antialias_gamma = 1.5;
    o.sampling_method = 2, o.jitter = false, o.jitter_amount = 0.5, o.library_paths = {"inc1", "inc2"};
    o.format = FileFormat::png, o.bits_per_channel = 16, o.output_alpha = true, o.declares = {{"Size", 3.5}};
    o.verbose = true, o.pause = true, o.threads = 6;
  });
}

TEST_F(IniFile, ExtraKeysPovrayAccepts) {
  write("x.ini", "Bits_Per_Color=16\nOutput_To_File=off\nOutput_File_Type=e\n");
  expect_parses_to({"x.ini"}, [](RenderOptions& o) {
    o.bits_per_channel = 16, o.write_file = false, o.format = FileFormat::exr;
  });
}

TEST_F(IniFile, SyntaxCommentsBlanksQuotesCaseAndCrlf) {
  write("s.ini",
        "; a comment line\n"
        "\n"
        "   \t\n"
        "  width = 16   ; trailing comment\r\n"
        "HEIGHT=12\r\n"
        "Output_File_Name=\"my file;1.png\"  ; the ';' inside quotes is kept\n"
        "Library_Path = \"with space\"\n"
        "declare = N = 2 \n");
  expect_parses_to({"s.ini"}, [](RenderOptions& o) {
    o.width = 16, o.height = 12, o.output = "my file;1.png", o.library_paths = {"with space"};
    o.declares = {{"N", 2.0}};
  });
}

TEST_F(IniFile, AntialiasAcceptsPovrayBooleanWords) {
  const std::vector<std::pair<std::string, bool>> words = {
      {"on", true}, {"ON", true}, {"true", true}, {"Yes", true}, {"1", true},
      {"off", false}, {"False", false}, {"no", false}, {"0", false}};
  for (const auto& [word, value] : words) {
    write("b.ini", "Jitter=" + std::string(value ? "off" : "on") + "\nAntialias=" + word + "\nJitter=" + word + "\n");
    const RenderOptions o = parse({"b.ini"});
    EXPECT_EQ(o.antialias, value) << word;
    EXPECT_EQ(o.jitter, value) << word;
  }
}

TEST_F(IniFile, SwitchLinesAreAllowed) {
  write("sw.ini", "+W16 +H12 +A0.2\n-J\nWidth=20\n");
  expect_parses_to({"sw.ini"}, [](RenderOptions& o) {
    o.width = 20, o.height = 12, o.antialias = true, o.antialias_threshold = 0.2, o.jitter = false;
  });
}

TEST_F(IniFile, SectionsAreSkippedUnlessSelected) {
  write("w.ini", "Width=16\n[A]\nHeight=10\n[B]\nHeight=20\n[a]\nWidth=30\n");
  expect_parses_to({"w.ini"}, [](RenderOptions& o) { o.width = 16; });
  expect_parses_to({"w.ini[b]"}, [](RenderOptions& o) { o.width = 16, o.height = 20; });
  expect_parses_to({"w.ini[A]"}, [](RenderOptions& o) { o.width = 30, o.height = 10; });
  EXPECT_EQ(usage_error({"w.ini[C]"}), "w.ini: no section [C]");

  RenderOptions direct;
  apply_ini_section("w.ini", "B", direct);
  EXPECT_EQ(direct.height, 20);
}

TEST_F(IniFile, ExtensionIsCaseInsensitive) {
  write("UPPER.INI", "Width=99\n");
  expect_parses_to({"UPPER.INI"}, [](RenderOptions& o) { o.width = 99; });
}

TEST_F(IniFile, LaterWinsBetweenIniAndSwitches) {
  write("a.ini", "Width=200\nHeight=100\n");
  expect_parses_to({"+W50", "a.ini"}, [](RenderOptions& o) { o.width = 200, o.height = 100; });
  expect_parses_to({"a.ini", "+W50"}, [](RenderOptions& o) { o.width = 50, o.height = 100; });
  expect_parses_to({"--height=7", "a.ini", "--width=8"}, [](RenderOptions& o) { o.width = 8, o.height = 100; });
  write("b.ini", "Width=300\n");
  expect_parses_to({"a.ini", "scene.pov", "b.ini"}, [](RenderOptions& o) {
    o.width = 300, o.height = 100, o.input = "scene.pov";
  });
}

TEST_F(IniFile, RelativeInputStaysRelativeToTheWorkingDirectory) {
  write("sub/s.ini", "Input_File_Name=scene.pov\nLibrary_Path=inc\n");
  expect_parses_to({"sub/s.ini"}, [](RenderOptions& o) { o.input = "scene.pov", o.library_paths = {"inc"}; });
}

TEST_F(IniFile, NestedIniFiles) {
  write("inner.ini", "Width=16\n");
  write("outer.ini", "inner.ini\nHeight=12\n");
  expect_parses_to({"outer.ini"}, [](RenderOptions& o) { o.width = 16, o.height = 12; });
  write("loop.ini", "loop.ini\n");
  EXPECT_NE(usage_error({"loop.ini"}).find("nested too deeply"), std::string::npos);
}

TEST_F(IniFile, ApplyIniFileDirectly) {
  write("d.ini", "Width=10\n");
  RenderOptions o;
  o.height = 5;
  apply_ini_file("d.ini", o);
  EXPECT_EQ(o.width, 10);
  EXPECT_EQ(o.height, 5);
}

struct IniErrorCase {
  std::string text;
  std::string message;  // the whole message, for a file named e.ini
};

void PrintTo(const IniErrorCase& c, std::ostream* out) { *out << ::testing::PrintToString(c.text); }

class IniErrors : public TempDir, public ::testing::WithParamInterface<IniErrorCase> {};

TEST_P(IniErrors, NameFileLineAndKey) {
  write("e.ini", GetParam().text);
  EXPECT_EQ(usage_error({"e.ini"}), GetParam().message);
}

INSTANTIATE_TEST_SUITE_P(Ini, IniErrors, ::testing::Values(
    IniErrorCase{"Width=16\nFoo=3\n", "e.ini:2: unknown key 'Foo'"},
    IniErrorCase{"; c\n\n  Bar = 1 ; x\n", "e.ini:3: unknown key 'Bar'"},
    IniErrorCase{"Width=abc\n", "e.ini:1: Width: expected a whole number from 1 to 65536, got 'abc'"},
    IniErrorCase{"Width=\n", "e.ini:1: Width: expected a whole number from 1 to 65536, got ''"},
    IniErrorCase{"Antialias=maybe\n",
                 "e.ini:1: Antialias: expected on/off, true/false, yes/no or 1/0, got 'maybe'"},
    IniErrorCase{"Declare=N=abc\n", "e.ini:1: Declare: the value of N must be a number, got 'abc'"},
    IniErrorCase{"Output_File_Type=Q\n",
                 "e.ini:1: Output_File_Type: unknown output file type 'Q' (N = PNG, E = EXR, P = PPM, T = TGA, "
                 "C = compressed TGA, J = JPEG, B = BMP, H = Radiance HDR)"},
    IniErrorCase{"Width=16\nAntialias\n", "e.ini:2: expected Key=Value, got 'Antialias'"},
    IniErrorCase{"// not a comment\n", "e.ini:1: expected Key=Value, got '// not a comment'"},
    IniErrorCase{"+W16 +Z9\n", "e.ini:1: unknown option '+Z9'"},
    IniErrorCase{"+Wx\n", "e.ini:1: +Wx: expected a whole number from 1 to 65536, got 'x'"},
    IniErrorCase{"missing.ini\n", "cannot read .ini file 'missing.ini'"}));

TEST_F(IniFile, UnreadableFileNamesThePath) {
  EXPECT_EQ(usage_error({"nope.ini"}), "cannot read .ini file 'nope.ini'");
  fs::create_directory("folder.ini");
  EXPECT_EQ(usage_error({"folder.ini"}), "cannot read .ini file 'folder.ini'");
}

// ---- Output path and encoding ---------------------------------------------------------------------

struct OutputCase {
  Change options;
  std::string path;
  FileFormat format;
  int bits;
  bool full_float;
};

void PrintTo(const OutputCase& c, std::ostream* out) { *out << c.path; }

class ResolvesOutput : public TempDir, public ::testing::WithParamInterface<OutputCase> {};

TEST_P(ResolvesOutput, PathAndEncoding) {
  fs::create_directory("existing");
  RenderOptions o;
  o.input = "scenes/ball.pov";
  GetParam().options(o);
  EXPECT_EQ(resolved_output_path(o).string(), GetParam().path);
  const image::EncodeOptions e = resolved_encoding(o);
  EXPECT_EQ(format_name(e.format), format_name(GetParam().format));
  EXPECT_EQ(e.bits_per_channel, GetParam().bits);
  EXPECT_EQ(e.exr_full_float, GetParam().full_float);
}

INSTANTIATE_TEST_SUITE_P(Output, ResolvesOutput, ::testing::Values(
    // Default: the scene's stem in the working directory, not the scene's folder.
    OutputCase{[](RenderOptions&) {}, "ball.png", FileFormat::png, 8, false},
    OutputCase{[](RenderOptions& o) { o.input.clear(); }, "object.png", FileFormat::png, 8, false},
    OutputCase{[](RenderOptions& o) { o.format = FileFormat::exr; }, "ball.exr", FileFormat::exr, 8, false},
    OutputCase{[](RenderOptions& o) { o.format = FileFormat::exr, o.exr_full_float = true; }, "ball.exr",
               FileFormat::exr, 8, true},
    OutputCase{[](RenderOptions& o) { o.format = FileFormat::exr, o.bits_per_channel = 16; }, "ball.exr",
               FileFormat::exr, 8, false},
    OutputCase{[](RenderOptions& o) { o.format = FileFormat::ppm, o.bits_per_channel = 16; }, "ball.ppm",
               FileFormat::ppm, 16, false},
    OutputCase{[](RenderOptions& o) { o.bits_per_channel = 16; }, "ball.png", FileFormat::png, 16, false},
    OutputCase{[](RenderOptions& o) { o.format = FileFormat::png, o.exr_full_float = true; }, "ball.png",
               FileFormat::png, 8, false},
    // An explicit name; its extension gives the format when no +F type is set.
    OutputCase{[](RenderOptions& o) { o.output = "out.exr"; }, "out.exr", FileFormat::exr, 8, false},
    OutputCase{[](RenderOptions& o) { o.output = "sub/out.EXR"; }, "sub/out.EXR", FileFormat::exr, 8, false},
    OutputCase{[](RenderOptions& o) { o.output = "out.ppm", o.bits_per_channel = 16; }, "out.ppm", FileFormat::ppm,
               16, false},
    OutputCase{[](RenderOptions& o) { o.output = "out.png", o.format = FileFormat::png; }, "out.png",
               FileFormat::png, 8, false},
    // POV-Ray appends the format's extension when the name lacks it.
    OutputCase{[](RenderOptions& o) { o.output = "out"; }, "out.png", FileFormat::png, 8, false},
    OutputCase{[](RenderOptions& o) { o.output = "out", o.format = FileFormat::exr; }, "out.exr", FileFormat::exr,
               8, false},
    OutputCase{[](RenderOptions& o) { o.output = "out.tga"; }, "out.tga", FileFormat::tga, 8, false},
    OutputCase{[](RenderOptions& o) { o.output = "out.jpg"; }, "out.jpg", FileFormat::jpeg, 8, false},
    OutputCase{[](RenderOptions& o) { o.output = "out.gif"; }, "out.gif.png", FileFormat::png, 8, false},
    OutputCase{[](RenderOptions& o) { o.output = "out.exr", o.format = FileFormat::png; }, "out.exr.png",
               FileFormat::png, 8, false},
    // A folder: trailing '/' (need not exist) or an existing folder gets the default name.
    OutputCase{[](RenderOptions& o) { o.output = "renders/"; }, "renders/ball.png", FileFormat::png, 8, false},
    OutputCase{[](RenderOptions& o) { o.output = "renders/", o.format = FileFormat::exr; }, "renders/ball.exr",
               FileFormat::exr, 8, false},
    OutputCase{[](RenderOptions& o) { o.output = "existing"; }, "existing/ball.png", FileFormat::png, 8, false}));

TEST(ResolvedOutput, FromTheCommandLine) {
  const RenderOptions o = parse({"+FN16", "+Orenders/", "scenes/glass.pov"});
  EXPECT_EQ(resolved_output_path(o).string(), "renders/glass.png");
  EXPECT_EQ(resolved_encoding(o).bits_per_channel, 16);
}

// ---- apply_switch and usage text ----------------------------------------------------------------

TEST(ApplySwitch, AcceptsEveryForm) {
  RenderOptions o;
  apply_switch("+w64", o);
  apply_switch("--height=32", o);
  apply_switch("Declare=K=1", o);
  apply_switch("Antialias=on", o);
  apply_switch("-h", o);
  RenderOptions expected;
  expected.width = 64, expected.height = 32, expected.declares = {{"K", 1.0}}, expected.antialias = true;
  expected.help = true;
  EXPECT_EQ(dump(o), dump(expected));
  EXPECT_THROW(apply_switch("--width", o), UsageError);
  EXPECT_THROW(apply_switch("scene.pov", o), UsageError);
}

TEST(Usage, ListsEveryOptionWithDefaults) {
  const std::string text = usage_text();
  for (const char* name : {"+I", "+O", "+W", "+H", "+A", "-A", "+AM", "+AG", "+R", "+J", "-J", "+L", "+F", "-F",
                           "+UA", "+WT", "+D", "+V", "+P", "Declare=", "--input", "--output", "-o FILE", "--width",
                           "--height", "--antialias", "--no-antialias", "--aa-depth", "--sampling-method", "--jitter",
                           "--no-jitter", "--library-path", "--format", "exr32", "ppm16", "--threads", "--declare",
                           "--alpha", "--stats", "--vs-povray", "--lighting", "--help", "-h", "--verbose",
                           "800x600", "threshold 0.3"}) {
    EXPECT_NE(text.find(name), std::string::npos) << name;
  }
}

}  // namespace
}  // namespace povtrace::app
