// POV-Ray 3.7's sample animations (issue 18): povtrace renders each case of reference/animation/cases.txt (a frame
// subset of one sample .ini, read from Debian's povray-examples, not copied into this repository) with the command
// POV-Ray's reference frames were made with (reference/make_animation_references.sh), and must write
//   - exactly the files POV-Ray wrote (frame names, debug.txt, the portfolio's #fopen HTML pages), no more, no less;
//   - every frame within the image regression thresholds of POV-Ray's (PSNR >= 50 dB, at most 0.1 % of pixels off
//     by more than 1/255, as tests/regression/render_and_compare.cmake asks of povdiff);
//   - every other file byte for byte as POV-Ray's (#debug text, #write output).
// Skipped when the sample scenes are not installed ($POVRAY_SAMPLES, default /usr/share/povray-3.7/scenes).

#include <sys/wait.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "renderer/image/compare.hpp"
#include "renderer/image/image.hpp"
#include "tests/common/scratch_folder.hpp"

namespace {

namespace fs = std::filesystem;

constexpr double kMinPsnr = 50.0;           // the regression thresholds (render_and_compare.cmake)
constexpr double kThreshold = 1.0 / 255.0;
constexpr double kMaxShare = 0.001;

struct Case {
  std::string name;      // reference/animation/NAME/
  std::string ini;       // relative to the sample scenes' root
  std::string switches;  // frame subset (+SF +EF +STP) or a fix, as written in cases.txt
};

const fs::path kReferences = fs::path(POVTRACE_SOURCE_DIR) / "reference" / "animation";

std::vector<Case> read_cases() {
  std::vector<Case> cases;
  std::ifstream in(kReferences / "cases.txt");
  for (std::string line; std::getline(in, line);) {
    std::istringstream fields(line);
    Case c;
    if (!(fields >> c.name) || c.name.starts_with('#')) continue;
    fields >> c.ini;
    std::getline(fields >> std::ws, c.switches);
    cases.push_back(c);
  }
  return cases;
}

fs::path samples_root() {
  const char* env = std::getenv("POVRAY_SAMPLES");
  return env && *env ? fs::path(env) : fs::path("/usr/share/povray-3.7/scenes");
}

std::set<std::string> names_in(const fs::path& folder) {
  std::set<std::string> names;
  for (const auto& entry : fs::directory_iterator(folder)) names.insert(entry.path().filename().string());
  return names;
}

std::string contents(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::string quoted(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

// Test names and failure messages show the case by name.
void PrintTo(const Case& c, std::ostream* os) { *os << c.name << " (" << c.ini << " " << c.switches << ")"; }

class AnimationSample : public ::testing::TestWithParam<Case> {};

TEST_P(AnimationSample, SameFilesAndFramesAsPovray) {
  const Case& c = GetParam();
  const fs::path ini = samples_root() / c.ini;
  if (!fs::is_directory(samples_root() / "animations") || !fs::is_directory(samples_root() / "portfolio"))
    GTEST_SKIP() << "POV-Ray's sample scenes are not installed in " << samples_root()
                 << " (Debian package povray-examples; or set POVRAY_SAMPLES)";
  ASSERT_TRUE(fs::exists(ini)) << ini << " is missing although the sample scenes are installed";
  const fs::path reference = kReferences / c.name;
  const std::set<std::string> expected = names_in(reference);
  ASSERT_TRUE(std::any_of(expected.begin(), expected.end(), [](const std::string& n) { return n.ends_with(".exr"); }))
      << reference << " holds no frame: run reference/make_animation_references.sh " << c.name;

  // The .ini's folder, copied: the scene runs from it as POV-Ray's did, and writes its files there.
  povtrace::test::ScratchFolder scratch;
  const fs::path run = scratch / "run";
  fs::copy(ini.parent_path(), run, fs::copy_options::recursive);
  const std::set<std::string> before = names_in(run);
  const fs::path log = scratch / "povtrace.log";
  const std::string command = "cd " + quoted(run.string()) + " && " + quoted(POVTRACE_EXE) + " -D " +
                              quoted(ini.filename().string()) + " +W160 +H120 +FE -A +GDdebug.txt " + c.switches +
                              " > " + quoted(log.string()) + " 2>&1";
  const int status = std::system(command.c_str());
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0)
      << "povtrace failed (status " << status << "): " << command << "\n" << contents(log);

  std::set<std::string> written;
  for (const std::string& n : names_in(run))
    if (!before.contains(n)) written.insert(n);
  EXPECT_EQ(written, expected) << "the files povtrace wrote (left) differ from POV-Ray's (right), " << command;

  for (const std::string& n : expected) {
    if (!written.contains(n)) continue;
    if (n.ends_with(".exr")) {
      const povtrace::image::Image theirs = povtrace::image::read_image(reference / n);
      const povtrace::image::Image ours = povtrace::image::read_image(run / n);
      ASSERT_EQ(ours.width, 160);
      ASSERT_EQ(ours.height, 120);
      const povtrace::image::CompareReport r = povtrace::image::compare_images(theirs, ours, kThreshold);
      EXPECT_GE(r.psnr, kMinPsnr) << c.name << ": frame " << n;
      EXPECT_LE(r.share_over_threshold, kMaxShare) << c.name << ": frame " << n << ", " << r.pixels_over_threshold
                                                   << " pixels off by more than 1/255";
    } else {
      EXPECT_EQ(contents(run / n), contents(reference / n)) << c.name << ": " << n << " differs from POV-Ray's";
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Samples, AnimationSample, ::testing::ValuesIn(read_cases()),
                         [](const ::testing::TestParamInfo<Case>& p) { return p.param.name; });

// The case list itself: read, and every case has its reference folder (a typo in cases.txt must not pass unseen).
TEST(AnimationSampleCases, EveryCaseHasReferences) {
  const std::vector<Case> cases = read_cases();
  EXPECT_GE(cases.size(), 20u);
  for (const Case& c : cases) {
    EXPECT_TRUE(c.ini.ends_with(".ini")) << c.name;
    EXPECT_TRUE(fs::is_directory(kReferences / c.name)) << c.name;
  }
}

}  // namespace
