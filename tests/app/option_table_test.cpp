// Tests of the POV-Ray 3.7 option table (app/option_table.cpp): every switch and INI key is accepted and sets
// its field (or warns once that it has no effect), a bad value is a UsageError naming the switch or key, the
// switch matcher takes the longest letters, povray.ini is found as POV-Ray does, Create_Ini reads back, and
// docs/switches.md is the table the program prints.

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "app/option_table.hpp"
#include "app/options.hpp"

namespace povtrace::app {
namespace {

namespace fs = std::filesystem;
using image::Dither;
using image::FileFormat;

RenderOptions parse(const std::vector<std::string>& args, const IniEnvironment* env = nullptr) {
  std::vector<const char*> argv{"povtrace"};
  for (const std::string& a : args) argv.push_back(a.c_str());
  return parse_command_line(static_cast<int>(argv.size()), argv.data(), env);
}

std::string joined(const std::vector<std::string>& args) {
  std::string text;
  for (const std::string& a : args) text += (text.empty() ? "" : " ") + a;
  return text;
}

std::string usage_error(const std::vector<std::string>& args) {
  try {
    parse(args);
  } catch (const UsageError& e) {
    return e.what();
  }
  return "";
}

bool warns(const RenderOptions& o, const std::string& part) {
  for (const std::string& w : o.warnings) {
    if (w.find(part) != std::string::npos) return true;
  }
  return false;
}

// ---- Every switch and key: the value lands in its field ---------------------------------------------

struct KeyCase {
  std::vector<std::string> args;
  std::function<bool(const RenderOptions&)> check;
};

void PrintTo(const KeyCase& c, std::ostream* out) { *out << "[" << joined(c.args) << "]"; }

class SetsField : public ::testing::TestWithParam<KeyCase> {};

TEST_P(SetsField, AndNothingIsRefused) {
  const RenderOptions o = parse(GetParam().args);
  EXPECT_TRUE(GetParam().check(o)) << joined(GetParam().args);
}

#define CHECK(expr) [](const RenderOptions& o) { return expr; }
using V = std::vector<std::string>;

INSTANTIATE_TEST_SUITE_P(LongestFirst, SetsField, ::testing::Values(
    KeyCase{V{"+HIx.inc"}, CHECK(o.include_header == fs::path("x.inc") && o.height == 600)},
    KeyCase{V{"+KFF2"}, CHECK(o.animation.final_frame == 2 && !o.animation.final_clock)},
    KeyCase{V{"+KFI3"}, CHECK(o.animation.initial_frame == 3 && !o.animation.final_clock)},
    KeyCase{V{"+KF0.5"}, CHECK(o.animation.final_clock == 0.5)},
    KeyCase{V{"+SF0.5"}, CHECK(o.animation.subset_start == 0.5)},
    KeyCase{V{"+STP2"}, CHECK(o.animation.frame_step == 2)},
    KeyCase{V{"+SU"}, CHECK(warns(o, "+SU / Split_Unions"))},
    KeyCase{V{"+Q9"}, CHECK(o.quality == 9)},
    KeyCase{V{"+MV3.7"}, CHECK(o.language_version == 3.7)},
    KeyCase{V{"-MV3.5"}, CHECK(o.language_version == 3.5)},
    KeyCase{V{"+HR"}, CHECK(warns(o, "High_Reproducibility") && o.height == 600)},
    KeyCase{V{"+RFI"}, CHECK(warns(o, "Radiosity_From_File"))},
    KeyCase{V{"+RFfile.rad"}, CHECK(warns(o, "Radiosity_File_Name"))},
    KeyCase{V{"+RS2"}, CHECK(warns(o, "Render_Block_Step") && o.antialias_depth == 3)},
    KeyCase{V{"+RTR"}, CHECK(warns(o, "Real_Time_Raytracing"))},
    KeyCase{V{"+WL3"}, CHECK(o.warning_level == 3 && o.width == 800)},
    KeyCase{V{"+KLA"}, CHECK(warns(o, "Clockless_Animation") && !o.animation.clock)}));

INSTANTIATE_TEST_SUITE_P(Input, SetsField, ::testing::Values(
    KeyCase{V{"+I-"}, CHECK(o.input == "-")},
    KeyCase{V{"Include_Header=h.inc"}, CHECK(o.include_header == fs::path("h.inc"))},
    KeyCase{V{"Version=3.1"}, CHECK(o.language_version == 3.1)},
    KeyCase{V{"Declare=S=\"hello world\""}, CHECK(o.string_declares.size() == 1 && o.string_declares[0].second == "hello world")},
    KeyCase{V{"Declare=S=\"a\"", "Declare=S=2"}, CHECK(o.string_declares.empty() && o.declares.size() == 1)},
    KeyCase{V{"Declare=S=2", "Declare=S=\"a\""}, CHECK(o.declares.empty() && o.string_declares.size() == 1)},
    KeyCase{V{"lib/"}, CHECK(o.library_paths == std::vector<fs::path>{"lib/"} && o.input.empty())},
    KeyCase{V{"scene.txt"}, CHECK(o.input == "scene.txt")}));

INSTANTIATE_TEST_SUITE_P(Output, SetsField, ::testing::Values(
    KeyCase{V{"+O-"}, CHECK(o.output == fs::path("-") && resolved_output_path(o) == "-")},
    KeyCase{V{"+FT"}, CHECK(o.format == FileFormat::tga)},
    KeyCase{V{"+FC"}, CHECK(o.format == FileFormat::tga_rle)},
    KeyCase{V{"+FJ"}, CHECK(o.format == FileFormat::jpeg)},
    KeyCase{V{"+FB"}, CHECK(o.format == FileFormat::bmp)},
    KeyCase{V{"+FH"}, CHECK(o.format == FileFormat::hdr)},
    KeyCase{V{"+FNg"}, CHECK(o.format == FileFormat::png && o.grayscale)},
    KeyCase{V{"+FP12"}, CHECK(o.format == FileFormat::ppm && o.bits_per_channel == 12)},
    KeyCase{V{"+FN4"}, CHECK(o.bits_per_channel == 5)},
    KeyCase{V{"+FN24"}, CHECK(o.bits_per_channel == 16)},
    KeyCase{V{"Output_File_Type=J"}, CHECK(o.format == FileFormat::jpeg)},
    KeyCase{V{"Bits_Per_Colour=10"}, CHECK(o.bits_per_channel == 10)},
    KeyCase{V{"Bits_Per_Color=2"}, CHECK(o.bits_per_channel == 5)},
    KeyCase{V{"Grayscale_Output=on"}, CHECK(o.grayscale)},
    KeyCase{V{"Compression=80"}, CHECK(o.compression == 80)},
    KeyCase{V{"Compression=300"}, CHECK(o.compression == 100)},
    KeyCase{V{"File_Gamma=2.2"}, CHECK(o.file_gamma == 2.2)},
    KeyCase{V{"File_Gamma=1.8", "File_Gamma=sRGB"}, CHECK(!o.file_gamma)},
    KeyCase{V{"+TH"}, CHECK(o.dither == Dither::floyd_steinberg)},
    KeyCase{V{"+THB2"}, CHECK(o.dither == Dither::bayer2)},
    KeyCase{V{"+THfs", "-TH"}, CHECK(o.dither == Dither::none && o.dither_method == Dither::floyd_steinberg)},
    KeyCase{V{"Dither_Method=D1", "Dither=on"}, CHECK(o.dither == Dither::diffusion1d)},
    KeyCase{V{"Dither=on", "Dither_Method=B4"}, CHECK(o.dither == Dither::bayer4)},
    KeyCase{V{"Dither_Method=B3"}, CHECK(o.dither == Dither::none && o.dither_method == Dither::bayer3)},
    KeyCase{V{"+AGsRGB"}, CHECK(o.antialias_gamma_srgb && o.antialias_gamma == 2.2)},
    KeyCase{V{"Antialias_Gamma=srgb", "Antialias_Gamma=1.5"}, CHECK(!o.antialias_gamma_srgb && o.antialias_gamma == 1.5)},
    KeyCase{V{"Display_Gamma=2.2"}, CHECK(warns(o, "Display_Gamma"))},
    KeyCase{V{"+MI128"}, CHECK(warns(o, "Max_Image_Buffer_Memory"))}));

INSTANTIATE_TEST_SUITE_P(RegionContinueQuality, SetsField, ::testing::Values(
    KeyCase{V{"+SR0.25", "+ER1", "+SC10", "+EC0.5"}, CHECK(o.region.start_row == 0.25 && o.region.end_row == 1.0 && o.region.start_column == 10.0 &&
             o.region.end_column == 0.5)},
    KeyCase{V{"Start_Row=3", "End_Row=7", "Start_Column=0.1", "End_Column=0.9"}, CHECK(o.region.start_row == 3.0 && o.region.end_row == 7.0 && o.region.start_column == 0.1 &&
             o.region.end_column == 0.9)},
    KeyCase{V{"+C"}, CHECK(o.continue_trace)}, KeyCase{V{"+C", "-C"}, CHECK(!o.continue_trace)},
    KeyCase{V{"Continue_Trace=yes"}, CHECK(o.continue_trace)},
    KeyCase{V{"+Q0"}, CHECK(o.quality == 0)}, KeyCase{V{"+Q10"}, CHECK(o.quality == 9)}, KeyCase{V{"Quality=11"}, CHECK(o.quality == 9)},
    KeyCase{V{"Quality=4"}, CHECK(o.quality == 4)}));

INSTANTIATE_TEST_SUITE_P(Animation, SetsField, ::testing::Values(
    KeyCase{V{"+K0.25"}, CHECK(o.animation.clock == 0.25)}, KeyCase{V{"Clock=2"}, CHECK(o.animation.clock == 2.0)},
    KeyCase{V{"+KI-1"}, CHECK(o.animation.initial_clock == -1.0)}, KeyCase{V{"Initial_Clock=0.5"}, CHECK(o.animation.initial_clock == 0.5)},
    KeyCase{V{"Final_Clock=3"}, CHECK(o.animation.final_clock == 3.0)},
    KeyCase{V{"Initial_Frame=0"}, CHECK(o.animation.initial_frame == 0)}, KeyCase{V{"Final_Frame=30"}, CHECK(o.animation.final_frame == 30)},
    KeyCase{V{"+KC"}, CHECK(o.animation.cyclic)}, KeyCase{V{"Cyclic_Animation=on", "-KC"}, CHECK(!o.animation.cyclic)},
    KeyCase{V{"+SF5", "+EF0.75"}, CHECK(o.animation.subset_start == 5.0 && o.animation.subset_end == 0.75)},
    KeyCase{V{"Subset_Start_Frame=0.1", "Subset_End_Frame=9"}, CHECK(o.animation.subset_start == 0.1 && o.animation.subset_end == 9.0)},
    KeyCase{V{"Frame_Step=3"}, CHECK(o.animation.frame_step == 3)}, KeyCase{V{"+STP0"}, CHECK(o.animation.frame_step == 1)},
    KeyCase{V{"+kf0.1666", "+kff20", "+kc", "declare=fp=0"}, CHECK(// splinefollow.ini's line
         o.animation.final_clock == 0.1666 && o.animation.final_frame == 20 && o.animation.cyclic &&
             o.declares.size() == 1)},
    KeyCase{V{"Clockless_Animation=off"}, CHECK(o.warnings.empty())},
    KeyCase{V{"+UF", "+UO"}, CHECK(warns(o, "Field_Render") && warns(o, "Odd_Field"))}));

INSTANTIATE_TEST_SUITE_P(Streams, SetsField, ::testing::Values(
    KeyCase{V{"-GA"}, CHECK(!o.streams.debug.console && !o.streams.fatal.console && !o.streams.render.console &&
                       !o.streams.statistics.console && !o.streams.warning.console)},
    KeyCase{V{"+GAall.log"}, CHECK(o.streams.all_file == fs::path("all.log") && o.streams.debug.console)},
    KeyCase{V{"+GDd.log"}, CHECK(o.streams.debug.file == fs::path("d.log") && o.streams.debug.console)},
    KeyCase{V{"-GFf.log"}, CHECK(o.streams.fatal.file == fs::path("f.log") && !o.streams.fatal.console)},
    KeyCase{V{"-GR"}, CHECK(!o.streams.render.console && !o.streams.render.file)},
    KeyCase{V{"+GSs.log"}, CHECK(o.streams.statistics.file == fs::path("s.log"))},
    KeyCase{V{"-GW"}, CHECK(!o.streams.warning.console)},
    KeyCase{V{"+GP"}, CHECK(o.streams.append)}, KeyCase{V{"Append_File=on"}, CHECK(o.streams.append)},
    KeyCase{V{"All_Console=off", "Warning_Console=on"}, CHECK(!o.streams.debug.console && o.streams.warning.console)},
    KeyCase{V{"All_File=a.log", "Debug_File=d.log", "Fatal_File=f.log", "Render_File=r.log", "Statistic_File=s.log",
           "Warning_File=w.log"}, CHECK(o.streams.all_file == fs::path("a.log") && o.streams.debug.file == fs::path("d.log") &&
             o.streams.fatal.file == fs::path("f.log") && o.streams.render.file == fs::path("r.log") &&
             o.streams.statistics.file == fs::path("s.log") && o.streams.warning.file == fs::path("w.log"))},
    KeyCase{V{"Debug_File=d.log", "Debug_File="}, CHECK(!o.streams.debug.file)},
    KeyCase{V{"Debug_Console=off", "Fatal_Console=off", "Render_Console=off", "Statistic_Console=off"}, CHECK(!o.streams.debug.console && !o.streams.fatal.console && !o.streams.render.console &&
             !o.streams.statistics.console && o.streams.warning.console)},
    KeyCase{V{"+GIout.ini"}, CHECK(o.create_ini == fs::path("out.ini"))}, KeyCase{V{"Create_Ini=c.ini"}, CHECK(o.create_ini == fs::path("c.ini"))},
    KeyCase{V{"Warning_Level=12"}, CHECK(o.warning_level == 9)}, KeyCase{V{"Warning_Level=0"}, CHECK(o.warning_level == 0)},
    KeyCase{V{"+V"}, CHECK(o.verbose)}));

INSTANTIATE_TEST_SUITE_P(ShellCommands, SetsField, ::testing::Values(
    KeyCase{V{"Pre_Scene_Command=echo %s", "Pre_Scene_Return=q"}, CHECK(o.shell_commands.pre_scene.command == "echo %s" && o.shell_commands.pre_scene.action == 'q' &&
             !o.shell_commands.pre_scene.negate)},
    KeyCase{V{"Post_Scene_Command=x", "Post_Scene_Return=!f"}, CHECK(o.shell_commands.post_scene.action == 'f' && o.shell_commands.post_scene.negate)},
    KeyCase{V{"Pre_Frame_Command=a", "Pre_Frame_Return=-S"}, CHECK(o.shell_commands.pre_frame.action == 's' && o.shell_commands.pre_frame.negate)},
    KeyCase{V{"Post_Frame_Command=b", "Post_Frame_Return=a"}, CHECK(o.shell_commands.post_frame.action == 'a')},
    KeyCase{V{"User_Abort_Command=c", "User_Abort_Return=u"}, CHECK(o.shell_commands.user_abort.command == "c")},
    KeyCase{V{"Fatal_Error_Command=d", "Fatal_Error_Return=i"}, CHECK(o.shell_commands.fatal_error.command == "d")},
    KeyCase{V{"--allow-shellout"}, CHECK(o.allow_shellout)}));

INSTANTIATE_TEST_SUITE_P(NoEffect, SetsField, ::testing::Values(
    KeyCase{V{"+D"}, CHECK(o.display && warns(o, "+D / Display"))}, KeyCase{V{"-D"}, CHECK(o.warnings.empty())},
    KeyCase{V{"+DGT"}, CHECK(o.display)}, KeyCase{V{"Video_Mode=G"}, CHECK(warns(o, "Video_Mode"))}, KeyCase{V{"Palette=3"}, CHECK(warns(o, "Palette"))},
    KeyCase{V{"+SP64", "+EP4", "+UD"}, CHECK(warns(o, "Preview_Start_Size") && warns(o, "Preview_End_Size") &&
                                    warns(o, "Draw_Vistas"))},
    KeyCase{V{"+P"}, CHECK(o.pause && warns(o, "Pause_When_Done"))},
    KeyCase{V{"+X"}, CHECK(warns(o, "Test_Abort"))}, KeyCase{V{"+X100"}, CHECK(warns(o, "Test_Abort"))},
    KeyCase{V{"Test_Abort_Count=100"}, CHECK(warns(o, "Test_Abort_Count"))},
    KeyCase{V{"-B"}, CHECK(o.warnings.empty())}, KeyCase{V{"Bounding=on"}, CHECK(o.warnings.empty())},
    KeyCase{V{"+MB"}, CHECK(warns(o, "Bounding_Threshold"))}, KeyCase{V{"+MB25"}, CHECK(warns(o, "Bounding_Threshold"))},
    KeyCase{V{"+BM2"}, CHECK(warns(o, "Bounding_Method"))},
    KeyCase{V{"BSP_BaseAccessCost=1", "BSP_ChildAccessCost=1.5", "BSP_ISectCost=2", "BSP_MaxDepth=64",
           "BSP_MissChance=0.2"}, CHECK(o.warnings.size() == 5)},
    KeyCase{V{"+UR", "+UL", "+UV"}, CHECK(warns(o, "Remove_Bounds") && warns(o, "Light_Buffer") && warns(o, "Vista_Buffer"))},
    KeyCase{V{"+BS16", "+RP3"}, CHECK(warns(o, "Render_Block_Size") && warns(o, "Render_Block_Pattern") == false &&
                                 warns(o, "Render_Pattern"))},
    KeyCase{V{"+RFO", "+RVP", "Radiosity_File_Name=x"}, CHECK(o.warnings.size() == 3)},
    KeyCase{V{"Buffer_Output=on", "Buffer_Size=0", "Create_Histogram=off", "Histogram_Name=h",
           "Histogram_Grid_Size=4.4", "Histogram_Type=C"}, CHECK(o.warnings.size() == 6)},
    KeyCase{V{"+UR", "Remove_Bounds=on", "+UR"}, CHECK(o.warnings.size() == 1)},
    KeyCase{V{"-display", ":0", "-geometry", "100x100", "-title", "t", "-visual", "TrueColor", "-icon"}, CHECK(o.warnings.size() == 5 && o.input.empty())},
    KeyCase{V{"--benchmark"}, CHECK(warns(o, "--benchmark"))},
    KeyCase{V{"--version"}, CHECK(o.version)}, KeyCase{V{"-version"}, CHECK(o.version)}, KeyCase{V{"--V"}, CHECK(o.version)},
    KeyCase{V{"-?"}, CHECK(o.help)}, KeyCase{V{"-help"}, CHECK(o.help)}));

#undef CHECK

// ---- Bad values: exit 2 with the switch or key named ---------------------------------------------------

class RefusesValue : public ::testing::TestWithParam<std::string> {};

TEST_P(RefusesValue, NamingTheSwitch) {
  const std::string message = usage_error({GetParam()});
  ASSERT_FALSE(message.empty()) << GetParam();
  EXPECT_NE(message.find(GetParam()), std::string::npos) << message;
}

INSTANTIATE_TEST_SUITE_P(Switches, RefusesValue, ::testing::Values(
    "+Kx", "+KIx", "+KFx", "+KFIx", "+KFF-1", "+KFF2.5", "+KCx", "+SFx", "+SF-1", "+EFx", "+STPx", "+SRx",
    "+SR-1", "+ERx", "+SCx", "+ECx", "+Cx", "+Qx", "+Q12", "+Q-1", "+MVx", "+MV9", "+MV0.5", "+WLx", "+HI",
    "+THx", "+TH1", "+FQ", "+FNx", "+FEg", "+FTg", "+MIx", "+BMx", "+BSx", "+RSx", "+RPx", "+SPx", "+EPx",
    "+URx", "+SUx", "+HRx", "+GPx", "+GI", "+RF", "+Xx", "+MBx", "+UFx", "+KLAx", "+AGx", "+AG-2", "+DGGG"));

INSTANTIATE_TEST_SUITE_P(IniKeys, RefusesValue, ::testing::Values(
    "Clock=x", "Initial_Clock=x", "Final_Clock=", "Initial_Frame=x", "Final_Frame=", "Cyclic_Animation=x",
    "Subset_Start_Frame=x", "Subset_End_Frame=-2", "Frame_Step=x", "Start_Row=x", "End_Row=x", "Start_Column=x",
    "End_Column=x", "Continue_Trace=x", "Quality=x", "Version=x", "Warning_Level=x", "Bits_Per_Color=x",
    "Bits_Per_Colour=x", "Grayscale_Output=x", "Compression=x", "File_Gamma=x", "File_Gamma=-1",
    "Display_Gamma=x", "Dither=x", "Dither_Method=B5", "Antialias_Gamma=x", "Output_File_Type=S",
    "Output_To_File=x", "Include_Ini=", "Pre_Scene_Return=x", "Post_Scene_Return=is", "Pre_Frame_Return=",
    "Post_Frame_Return=z", "User_Abort_Return=-", "Fatal_Error_Return=!x", "All_Console=x", "Debug_Console=x",
    "Fatal_Console=x", "Render_Console=x", "Statistic_Console=x", "Warning_Console=x", "Append_File=x",
    "Create_Ini=", "Verbose=x", "Bounding=x", "Bounding_Threshold=x", "Bounding_Method=x",
    "BSP_BaseAccessCost=x", "BSP_ChildAccessCost=x", "BSP_ISectCost=x", "BSP_MaxDepth=x", "BSP_MissChance=x",
    "Remove_Bounds=x", "Split_Unions=x", "Light_Buffer=x", "Vista_Buffer=x", "Render_Block_Size=x",
    "Render_Block_Step=x", "Render_Pattern=x", "Radiosity_File_Name=", "Radiosity_From_File=x",
    "Radiosity_To_File=x", "Radiosity_Vain_Pretrace=x", "Real_Time_Raytracing=x", "High_Reproducibility=x",
    "Clockless_Animation=x", "Field_Render=x", "Odd_Field=x", "Preview_Start_Size=x", "Preview_End_Size=x",
    "Draw_Vistas=x", "Test_Abort=x", "Test_Abort_Count=x", "Max_Image_Buffer_Memory=x", "Display=x",
    "Pause_When_Done=x", "Work_Threads=x", "Width=x", "Height=x", "Antialias=x", "Antialias_Threshold=x",
    "Antialias_Depth=x", "Sampling_Method=x", "Jitter=x", "Jitter_Amount=x", "Output_Alpha=x",
    "Input_File_Name=", "Library_Path=", "Declare=x"));

TEST(OptionTable, EveryOtherIniKeyRefusesNonsense) {
  // The rows whose value is free text (commands, names) have no bad value; every other key refuses one.
  const std::vector<std::string> free_text = {"Output_File_Name", "Include_Header", "All_File", "Debug_File",
                                              "Fatal_File", "Render_File", "Statistic_File", "Warning_File",
                                              "Video_Mode", "Palette", "Buffer_Output", "Buffer_Size",
                                              "Create_Histogram", "Histogram_Name", "Histogram_Grid_Size",
                                              "Histogram_Type", "Pre_Scene_Command", "Post_Scene_Command",
                                              "Pre_Frame_Command", "Post_Frame_Command", "User_Abort_Command",
                                              "Fatal_Error_Command", "Input_File_Name", "Library_Path",
                                              "Radiosity_File_Name", "Create_Ini"};
  std::vector<std::string> keys;
  for (const detail::OptionRow& row : detail::option_rows()) keys.emplace_back(row.ini_key);
  EXPECT_EQ(keys.size(), 111u) << "a row was added or removed: update docs/switches.md and the tests";
  for (const std::string& key : keys) {
    if (std::find(free_text.begin(), free_text.end(), key) != free_text.end()) continue;
    EXPECT_FALSE(usage_error({key + "=x_not_valid"}).empty()) << key;
  }
}

TEST(OptionTable, KeysOfThePlanAreAllThere) {
  // POV-Ray 3.7's INI table (processrenderoptions.cpp), every key.
  const char* keys[] = {
      "All_Console", "All_File", "Antialias_Depth", "Antialias", "Antialias_Threshold", "Antialias_Gamma",
      "Append_File", "Bits_Per_Color", "Bits_Per_Colour", "Bounding", "Bounding_Method", "Bounding_Threshold",
      "BSP_BaseAccessCost", "BSP_ChildAccessCost", "BSP_ISectCost", "BSP_MaxDepth", "BSP_MissChance",
      "Buffer_Output", "Buffer_Size", "Clock", "Clockless_Animation", "Compression", "Continue_Trace",
      "Create_Histogram", "Create_Ini", "Cyclic_Animation", "Debug_Console", "Debug_File", "Declare", "Display",
      "Display_Gamma", "Dither", "Dither_Method", "Draw_Vistas", "End_Column", "End_Row", "Fatal_Console",
      "Fatal_Error_Command", "Fatal_Error_Return", "Fatal_File", "Field_Render", "File_Gamma", "Final_Clock",
      "Final_Frame", "Frame_Step", "Grayscale_Output", "Height", "High_Reproducibility", "Histogram_Name",
      "Histogram_Grid_Size", "Histogram_Type", "Initial_Clock", "Initial_Frame", "Input_File_Name",
      "Include_Header", "Include_Ini", "Jitter_Amount", "Jitter", "Library_Path", "Light_Buffer",
      "Max_Image_Buffer_Memory", "Odd_Field", "Output_Alpha", "Output_File_Name", "Output_File_Type",
      "Output_To_File", "Palette", "Pause_When_Done", "Post_Frame_Command", "Post_Frame_Return",
      "Post_Scene_Command", "Post_Scene_Return", "Preview_End_Size", "Preview_Start_Size", "Pre_Frame_Command",
      "Pre_Frame_Return", "Pre_Scene_Command", "Pre_Scene_Return", "Quality", "Radiosity_File_Name",
      "Radiosity_From_File", "Radiosity_To_File", "Radiosity_Vain_Pretrace", "Real_Time_Raytracing",
      "Remove_Bounds", "Render_Block_Size", "Render_Block_Step", "Render_Console", "Render_File", "Render_Pattern",
      "Sampling_Method", "Split_Unions", "Start_Column", "Start_Row", "Statistic_Console", "Statistic_File",
      "Subset_End_Frame", "Subset_Start_Frame", "Test_Abort_Count", "Test_Abort", "User_Abort_Command",
      "User_Abort_Return", "Verbose", "Version", "Video_Mode", "Vista_Buffer", "Warning_Console", "Warning_File",
      "Warning_Level", "Width", "Work_Threads"};
  // And its switch table.
  const char* switches[] = {"AG", "AM", "A", "BM", "BS", "B", "C", "D", "EC", "EF", "EP", "ER", "F", "GA", "GD",
                            "GF", "GI", "GP", "GR", "GS", "GW", "HI", "HR", "H", "I", "J", "KC", "KI", "KFF",
                            "KFI", "KF", "KLA", "K", "L", "MB", "MI", "MV", "O", "P", "Q", "RFI", "RFO", "RF",
                            "RS", "RP", "RTR", "RVP", "R", "SC", "SF", "SP", "SR", "STP", "SU", "TH", "UA", "UD",
                            "UF", "UL", "UO", "UR", "UV", "V", "WL", "WT", "W", "X"};
  const auto rows = detail::option_rows();
  for (const char* key : keys) {
    EXPECT_TRUE(std::any_of(rows.begin(), rows.end(), [&](const auto& r) { return r.ini_key == key; })) << key;
  }
  for (const char* letters : switches) {
    EXPECT_TRUE(std::any_of(rows.begin(), rows.end(), [&](const auto& r) { return r.switch_letters == letters; }))
        << letters;
  }
  EXPECT_EQ(std::size(keys), rows.size());
}

// ---- povray.ini -----------------------------------------------------------------------------------------

class PovrayIni : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("povtrace_povrayini_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "home" / ".povray" / "3.7");
    fs::create_directories(dir_ / "cwd");
    env_.home = (dir_ / "home").string();
    env_.system_ini = dir_ / "system.ini";
    env_.working_directory = dir_ / "cwd";
  }
  void TearDown() override { fs::remove_all(dir_); }
  void write(const fs::path& p, const std::string& text) { std::ofstream(p) << text; }
  fs::path dir_;
  IniEnvironment env_;
};

TEST_F(PovrayIni, SearchOrderAsPovray) {
  EXPECT_FALSE(find_povray_ini(env_));
  write(dir_ / "home" / ".povrayrc", "Width=5\n");
  EXPECT_EQ(find_povray_ini(env_), dir_ / "home" / ".povrayrc");
  write(env_.system_ini, "Width=4\n");
  EXPECT_EQ(find_povray_ini(env_), env_.system_ini);
  write(dir_ / "home" / ".povray" / "3.7" / "povray.ini", "Width=3\n");
  EXPECT_EQ(find_povray_ini(env_), dir_ / "home" / ".povray" / "3.7" / "povray.ini");
  write(dir_ / "cwd" / "povray.ini", "Width=2\n");
  EXPECT_EQ(find_povray_ini(env_), dir_ / "cwd" / "povray.ini");
  write(dir_ / "povini.ini", "Width=1\n");
  env_.povini = (dir_ / "povini.ini").string();
  EXPECT_EQ(find_povray_ini(env_), dir_ / "povini.ini");
  EXPECT_EQ(parse({}, &env_).width, 1);
  EXPECT_EQ(parse({"+W7"}, &env_).width, 7);                   // read before the command line
  EXPECT_EQ(parse({"--no-povray-ini"}, &env_).width, 800);
  EXPECT_EQ(parse({}).width, 800);                              // no environment: none read
}

TEST_F(PovrayIni, MissingPovIniWarnsAndFallsBack) {
  write(env_.system_ini, "Height=9\n");
  env_.povini = (dir_ / "nope.ini").string();
  const RenderOptions o = parse({}, &env_);
  EXPECT_EQ(o.height, 9);
  EXPECT_TRUE(warns(o, "$POVINI"));
}

TEST_F(PovrayIni, ItsNoEffectSettingsDoNotWarn) {
  // Debian's /etc/povray/3.7/povray.ini sets Display=On and Bounding_Threshold=3.
  write(env_.system_ini, "Display=On\nBounding_Threshold=3\nVerbose=On\n");
  const RenderOptions o = parse({}, &env_);
  EXPECT_TRUE(o.display && o.verbose);
  EXPECT_TRUE(o.warnings.empty());
  EXPECT_TRUE(warns(parse({"+D"}, &env_), "Display"));
}

TEST_F(PovrayIni, IncludeIniReadsInPlace) {
  write(dir_ / "inner.ini", "Width=11\n");
  write(dir_ / "outer.ini", "Width=3\nInclude_Ini=" + (dir_ / "inner.ini").string() + "\nHeight=12\n");
  const RenderOptions o = parse({(dir_ / "outer.ini").string()});
  EXPECT_EQ(o.width, 11);
  EXPECT_EQ(o.height, 12);
  write(dir_ / "loop.ini", "Include_Ini=" + (dir_ / "loop.ini").string() + "\n");
  EXPECT_NE(usage_error({(dir_ / "loop.ini").string()}).find("nested too deeply"), std::string::npos);
}

// ---- Create_Ini -------------------------------------------------------------------------------------------

TEST(CreateIni, ReadsBackToTheSameOptions) {
  const std::vector<std::string> args = {
      "+Iscene.pov", "+HIhead.inc", "+Lone", "+Ltwo dir", "+MV3.6", "Declare=A=1.25", "Declare=S=\"x y\"",
      "+Oout/x.png", "+W321", "+H123", "+FN12", "+FNg", "Compression=55", "+UA", "File_Gamma=1.8", "+THB3",
      "+A0.1", "+R5", "+AM2", "+AGsRGB", "-J0.5", "+K0.3", "+KI1", "+KF2", "+KFI3", "+KFF40", "+KC", "+STP2",
      "+SF0.25", "+EF30", "+SR0.1", "+ER0.9", "+SC5", "+EC50", "+C", "+Q5", "+WT3", "+V", "+GAall.log", "-GA",
      "+GDd.log", "+GWw.log", "+GP", "+WL4", "Pre_Scene_Command=echo %s", "Pre_Scene_Return=!q",
      "Fatal_Error_Command=true", "Fatal_Error_Return=f"};
  const RenderOptions original = parse(args);
  const fs::path ini = fs::temp_directory_path() / ("povtrace_create_ini_" + std::to_string(::getpid()) + ".ini");
  std::ofstream(ini) << ini_text(original);
  const RenderOptions again = parse({ini.string()});
  fs::remove(ini);
  EXPECT_EQ(ini_text(again), ini_text(original));
  EXPECT_EQ(again.input, original.input);
  EXPECT_EQ(again.library_paths, original.library_paths);
  EXPECT_EQ(again.string_declares, original.string_declares);
  EXPECT_EQ(again.declares, original.declares);
  EXPECT_EQ(again.animation.subset_start, 0.25);
  EXPECT_EQ(again.dither, Dither::bayer3);
  EXPECT_TRUE(again.antialias_gamma_srgb);
  EXPECT_EQ(again.streams.warning.file, fs::path("w.log"));
  EXPECT_FALSE(again.streams.render.console);
  EXPECT_EQ(again.shell_commands.pre_scene.command, "echo %s");
  EXPECT_TRUE(again.shell_commands.pre_scene.negate);
}

// ---- The switch table ---------------------------------------------------------------------------------------

TEST(SwitchTable, DocsHoldTheGeneratedTable) {
  const char* source = std::getenv("POVTRACE_SOURCE_DIR");
  if (source == nullptr) GTEST_SKIP() << "POVTRACE_SOURCE_DIR not set";
  std::ifstream in(fs::path(source) / "docs" / "switches.md");
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_NE(text.str().find(switch_table_markdown()), std::string::npos)
      << "docs/switches.md is stale: regenerate its table with `povtrace --switch-table`";
}

TEST(SwitchTable, OneRowPerKeyAndManPage) {
  const std::string table = switch_table_markdown();
  for (const detail::OptionRow& row : detail::option_rows()) {
    EXPECT_NE(table.find("| " + std::string(row.ini_key) + " |"), std::string::npos) << row.ini_key;
  }
  const std::string man = man_page();
  EXPECT_EQ(man.rfind(".TH POVTRACE 1", 0), 0u);
  EXPECT_NE(man.find("Include_Header"), std::string::npos);
  EXPECT_NE(version_text().find("POV-Ray 3.7"), std::string::npos);
}

}  // namespace
}  // namespace povtrace::app
