// The povdiff program: exit status 0 within tolerance, 1 outside, 2 bad input; summary line last.
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "renderer/image/image.hpp"
#include "tests/common/scratch_folder.hpp"

namespace povtrace::image {
namespace {

using test::ScratchFolder;

#ifdef POVDIFF_EXECUTABLE

struct RunResult {
  int status = -1;
  std::string out;
  std::string err;
};

// Built with += because GCC 12 gives a false -Wrestrict warning for "literal" + std::string&&.
std::string quoted(const std::filesystem::path& path) {
  std::string text = "'";
  text += path.string();
  text += "'";
  return text;
}

RunResult run_povdiff(const ScratchFolder& folder, const std::string& arguments) {
  std::string command = quoted(POVDIFF_EXECUTABLE);
  command += " " + arguments;
  command += " > " + quoted(folder / "out.txt");
  command += " 2> " + quoted(folder / "err.txt");
  const int raw = std::system(command.c_str());
  RunResult result;
  result.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  result.out = test::read_bytes(folder / "out.txt");
  result.err = test::read_bytes(folder / "err.txt");
  return result;
}

std::string last_line(const std::string& text) {
  std::istringstream lines(text);
  std::string line, last;
  while (std::getline(lines, line)) last = line;
  return last;
}

// Two 10×10 PNGs that differ in `changed` pixels by `step` codes in red.
void write_pair(const ScratchFolder& folder, int changed, int step) {
  Image a(10, 10);
  a.encoding = Encoding::encoded;
  for (std::size_t i = 0; i < a.rgba.size(); ++i) {
    if (i % 4 != 3) a.rgba[i] = 0.5f;
  }
  Image b = a;
  for (int i = 0; i < changed; ++i) b.pixel(i, 0)[0] = (128.0f + float(step)) / 255.0f;
  EncodeOptions options;
  options.format = FileFormat::png;
  write_image(a, folder / "a.png", options);
  write_image(b, folder / "b.png", options);
  write_image(Image(5, 5), folder / "small.png", options);
}

class Povdiff : public ::testing::Test {
 protected:
  ScratchFolder folder;
  std::string a = quoted(folder / "a.png");
  std::string b = quoted(folder / "b.png");
};

TEST_F(Povdiff, IdenticalImagesPass) {
  write_pair(folder, 0, 0);
  const RunResult r = run_povdiff(folder, a + " " + b);
  EXPECT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_EQ(last_line(r.out), "povdiff: rmse=0 psnr=inf max=0 over=0 share=0 verdict=pass");
}

TEST_F(Povdiff, LargeDifferenceFails) {
  write_pair(folder, 5, 40);
  const RunResult r = run_povdiff(folder, a + " " + b + " --threshold 1/255");
  EXPECT_EQ(r.status, 1) << r.out << r.err;
  EXPECT_NE(last_line(r.out).find("over=5 share=0.05 verdict=fail"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("at (0, 0) channel R"), std::string::npos) << r.out;
}

TEST_F(Povdiff, ToleranceOptionsDecide) {
  write_pair(folder, 1, 1);  // one pixel one code off: PSNR = 20·log10(255·√300) ≈ 72.9 dB, share 1 %
  EXPECT_EQ(run_povdiff(folder, a + " " + b).status, 0);  // 1 code is not over 1/255
  EXPECT_EQ(run_povdiff(folder, a + " " + b + " --threshold=0").status, 1);
  EXPECT_EQ(run_povdiff(folder, a + " " + b + " --threshold 0 --max-share 0.01").status, 0);
  EXPECT_EQ(run_povdiff(folder, a + " " + b + " --min-psnr 80").status, 1);
}

TEST_F(Povdiff, WritesDifferenceMap) {
  write_pair(folder, 3, 10);
  const RunResult r = run_povdiff(folder, a + " " + b + " --diff " + quoted(folder / "heat.png"));
  EXPECT_EQ(r.status, 1) << r.out << r.err;
  const Image heat = read_image(folder / "heat.png");
  EXPECT_EQ(heat.width, 10);
  EXPECT_GT(heat.pixel(0, 0)[0], 0.5f);  // 10 codes ≈ 2.5·threshold: on the green → yellow ramp
  EXPECT_EQ(heat.pixel(5, 5)[0], 0.0f);
}

TEST_F(Povdiff, BadInputExitsWithTwo) {
  write_pair(folder, 0, 0);
  const std::string missing = quoted(folder / "missing.png");
  const std::string small = quoted(folder / "small.png");
  EXPECT_EQ(run_povdiff(folder, a + " " + missing).status, 2);
  EXPECT_NE(run_povdiff(folder, a + " " + missing).err.find("missing.png"), std::string::npos);
  EXPECT_EQ(run_povdiff(folder, a + " " + small).status, 2);
  EXPECT_EQ(run_povdiff(folder, a).status, 2);
  EXPECT_EQ(run_povdiff(folder, a + " " + b + " --threshold abc").status, 2);
  EXPECT_EQ(run_povdiff(folder, a + " " + b + " --threshold 1/0").status, 2);
  EXPECT_EQ(run_povdiff(folder, a + " " + b + " --bogus 1").status, 2);
  EXPECT_EQ(run_povdiff(folder, a + " " + b + " --min-psnr").status, 2);
  EXPECT_EQ(run_povdiff(folder, a + " " + b + " --diff out.gif").status, 2);
}

TEST_F(Povdiff, HelpPrintsUsage) {
  const RunResult r = run_povdiff(folder, "--help");
  EXPECT_EQ(r.status, 0);
  EXPECT_NE(r.out.find("usage: povdiff"), std::string::npos);
}

#else

TEST(Povdiff, NotBuilt) { GTEST_SKIP() << "the povdiff target was not available when configuring"; }

#endif

}  // namespace
}  // namespace povtrace::image
