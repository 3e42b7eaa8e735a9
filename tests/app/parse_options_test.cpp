// The parser's side of the POV-Ray options (ParseOptions): Declare=N="text" string declares, +HI Include_Header,
// +MV the initial #version, +WL Warning_Level and the classified message sink behind the +G streams. What the
// scene sees is read back from its #debug text.

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "parser/parse_scene.hpp"

namespace povtrace {
namespace {

namespace fs = std::filesystem;

struct Captured {
  std::string debug, warnings;
};

Captured parse_capturing(const std::string& text, ParseOptions options) {
  Captured c;
  options.classified_sink = [&](ParseOptions::MessageKind kind, const std::string& message) {
    (kind == ParseOptions::MessageKind::debug ? c.debug : c.warnings) += message;
  };
  parse_scene_text(text, "main.pov", options);
  return c;
}

TEST(ParseOptions, StringDeclares) {
  ParseOptions o;
  o.string_declares = {{"Name", "hello world"}};
  o.declares = {{"N", 2}};
  EXPECT_EQ(parse_capturing("#debug concat(Name, \" \", str(N,0,0), \"\\n\")\n", o).debug, "hello world 2\n");
}

TEST(ParseOptions, InitialVersion) {
  ParseOptions o;
  EXPECT_EQ(parse_capturing("#debug str(version,0,2)\n", o).debug, "3.70");
  o.initial_language_version = 350;
  EXPECT_EQ(parse_capturing("#debug str(version,0,2)\n", o).debug, "3.50");
  EXPECT_EQ(parse_capturing("#version 3.6;\n#debug str(version,0,2)\n", o).debug, "3.60");
}

TEST(ParseOptions, WarningLevel) {
  ParseOptions o;
  const std::string scene = "#warning \"careful\"\n#debug \"after\"\n";
  EXPECT_NE(parse_capturing(scene, o).warnings.find("careful"), std::string::npos);
  o.warning_level = 4;
  const Captured quiet = parse_capturing(scene, o);
  EXPECT_EQ(quiet.warnings, "");
  EXPECT_EQ(quiet.debug, "after");
  o.warning_level = 5;
  EXPECT_NE(parse_capturing(scene, o).warnings.find("careful"), std::string::npos);
}

class IncludeHeader : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("povtrace_header_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name) << text;
    return dir_ / name;
  }
  fs::path dir_;
};

TEST_F(IncludeHeader, IsReadBeforeTheSceneAndItsDeclaresStay) {
  ParseOptions o;
  o.include_header = write("head.inc", "#declare R = 0.5;\n#debug \"header \"\n");
  EXPECT_EQ(parse_capturing("#debug concat(\"scene \", str(R,0,1))\n", o).debug, "header scene 0.5");
}

TEST_F(IncludeHeader, IsFoundOnTheLibraryPath) {
  write("lib.inc", "#declare L = 3;\n");
  ParseOptions o;
  o.library_paths = {dir_};
  o.include_header = "lib.inc";
  EXPECT_EQ(parse_capturing("#debug str(L,0,0)\n", o).debug, "3");
}

TEST_F(IncludeHeader, ErrorsNameTheHeaderAndTheScene) {
  ParseOptions o;
  o.include_header = write("bad.inc", "\n  oops\n");
  try {
    parse_scene_text("sphere { 0, 1 }\n", "main.pov", o);
    FAIL() << "no error";
  } catch (const ParseError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("bad.inc:2:3: error"), std::string::npos) << message;
    EXPECT_NE(message.find("included from main.pov:1:1"), std::string::npos) << message;
  }
  o.include_header = "missing.inc";
  try {
    parse_scene_text("sphere { 0, 1 }\n", "main.pov", o);
    FAIL() << "no error";
  } catch (const ParseError& e) {
    EXPECT_NE(std::string(e.what()).find("cannot find the Include_Header file \"missing.inc\""), std::string::npos)
        << e.what();
  }
}

TEST_F(IncludeHeader, SceneErrorsKeepTheirPosition) {
  ParseOptions o;
  o.include_header = write("ok.inc", "#declare A = 1;\n\n\n");
  try {
    parse_scene_text("#declare B = 2;\n  nonsense\n", "main.pov", o);
    FAIL() << "no error";
  } catch (const ParseError& e) {
    EXPECT_NE(std::string(e.what()).find("main.pov:2:3: error"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace povtrace
