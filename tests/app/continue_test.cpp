// +C / Continue_Trace (issue 18): the render state file and POV-Ray 3.7's rules around it, in-process. State
// files are made here from an uninterrupted render's framebuffer with StateWriter, as an interrupted render leaves
// them; tests/app/interrupt_test.cpp interrupts the real program and continues it.
#include <gtest/gtest.h>

#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "app/animation.hpp"
#include "app/options.hpp"
#include "app/render_job.hpp"
#include "app/render_state.hpp"
#include "parser/parse_scene.hpp"
#include "scene/source.hpp"

namespace {

using namespace povtrace;
using image::PixelRect;
using Status = app::SavedState::Status;
namespace fs = std::filesystem;

fs::path source_dir() {
  const char* dir = std::getenv("POVTRACE_SOURCE_DIR");
  return dir ? fs::path(dir) : fs::path(".");
}

class Scratch {
 public:
  Scratch() {
    std::string pattern = (fs::temp_directory_path() / "povtrace_continue_XXXXXX").string();
    if (!::mkdtemp(pattern.data())) throw std::runtime_error("mkdtemp failed");
    path_ = pattern;
  }
  ~Scratch() { fs::remove_all(path_); }
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

std::string read_file(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

void write_file(const fs::path& p, const std::string& bytes) {
  std::ofstream out(p, std::ios::binary);
  out << bytes;
}

std::set<std::string> names_in(const fs::path& folder) {
  std::set<std::string> names;
  for (const auto& entry : fs::directory_iterator(folder)) names.insert(entry.path().filename().string());
  return names;
}

// 150 × 100 (block edges inside the image both ways), method 1 antialiasing with jitter (it compares pixels within
// a block), alpha; the scene copied into the scratch folder; messages to log.txt only.
app::RenderOptions options_in(const Scratch& s) {
  app::RenderOptions o;
  o.input = s.path() / "scene.pov";
  if (!fs::exists(o.input)) fs::copy_file(source_dir() / "scenes" / "checker_sphere.pov", o.input);
  o.output = s.path() / "out.png";
  o.width = 150;
  o.height = 100;
  o.antialias = true;
  o.antialias_threshold = 0.05;
  o.jitter = true;
  o.output_alpha = true;
  o.threads = 2;
  for (app::MessageStream* m : {&o.streams.debug, &o.streams.fatal, &o.streams.render, &o.streams.statistics,
                                &o.streams.warning})
    m->console = false;
  o.streams.all_file = s.path() / "log.txt";
  return o;
}

app::JobResult run(const app::RenderOptions& o) {
  std::atomic<bool> never{false};
  return app::run_render(o, never);
}

// The blocks of the 32-pixel grid of a 150 × 100 frame.
std::vector<PixelRect> blocks_of(int width, int height) {
  std::vector<PixelRect> blocks;
  for (int y = 0; y < height; y += 32)
    for (int x = 0; x < width; x += 32) blocks.push_back({x, y, std::min(x + 31, width - 1), std::min(y + 31, height - 1)});
  return blocks;
}

std::string settings_for(const app::RenderOptions& o) {
  return app::state_settings(o, app::plan_frames(o.animation).at(0), std::nullopt, 32, read_text_file(o.input));
}

// What an interrupted render leaves: a state file holding `blocks` of `image`.
void write_state(const app::RenderOptions& o, const image::Image& image, const std::vector<PixelRect>& blocks) {
  app::StateWriter writer(app::state_file_path(*o.output), settings_for(o), std::nullopt, 0.0);
  for (const PixelRect& b : blocks) writer.record(image, b);
  writer.finish_interrupted(image);
}

bool same_pixels(const image::Image& a, const image::Image& b) {
  return a.width == b.width && a.height == b.height && a.rgba == b.rgba;
}

TEST(StateFile, NameFollowsPovRaysRule) {
  EXPECT_EQ(app::state_file_path("dir/out.png"), fs::path("dir/out.povtrace-state"));
  EXPECT_EQ(app::state_file_path("a.b.exr"), fs::path("a.b.povtrace-state"));
  EXPECT_EQ(app::state_file_path("frame07.tga"), fs::path("frame07.povtrace-state"));
}

// Nothing touches the disk until the delay has passed; then the blocks noted so far are written with the new one.
TEST(StateFile, WrittenOnlyOnceTheDelayHasPassed) {
  const Scratch s;
  const app::RenderOptions o = options_in(s);
  image::Image img(150, 100);
  for (std::size_t i = 0; i < img.rgba.size(); ++i) img.rgba[i] = static_cast<float>(i % 97) / 7.0f;
  const fs::path path = s.path() / "out.povtrace-state";
  const std::vector<PixelRect> all = blocks_of(150, 100);
  app::StateWriter writer(path, settings_for(o), std::nullopt, 0.2);
  writer.record(img, all[0]);
  writer.record(img, all[4]);
  EXPECT_FALSE(fs::exists(path));
  std::this_thread::sleep_for(std::chrono::milliseconds(250));
  writer.record(img, all[7]);
  EXPECT_TRUE(fs::exists(path));
  writer.finish_interrupted(img);
  const app::SavedState read = app::read_state(path, settings_for(o), 150, 100);
  ASSERT_EQ(read.status, Status::usable);
  EXPECT_EQ(read.blocks, (std::vector<PixelRect>{all[0], all[4], all[7]}));
  for (const PixelRect& b : read.blocks)
    for (int y = b.y0; y <= b.y1; ++y)
      for (int x = b.x0; x <= b.x1; ++x)
        for (int c = 0; c < 4; ++c) ASSERT_EQ(read.pixels.pixel(x, y)[c], img.pixel(x, y)[c]);
  EXPECT_EQ(read.pixels.pixel(149, 99)[0], 0.0f);   // not saved: zero
}

// A continued render appends after the intact records; a damaged tail is cut off first, not left in between.
TEST(StateFile, ResumeAppendsAfterTheIntactRecords) {
  const Scratch s;
  const app::RenderOptions o = options_in(s);
  image::Image img(150, 100);
  for (std::size_t i = 0; i < img.rgba.size(); ++i) img.rgba[i] = static_cast<float>(i % 89);
  const fs::path path = s.path() / "out.povtrace-state";
  const std::vector<PixelRect> all = blocks_of(150, 100);
  {
    app::StateWriter writer(path, settings_for(o), std::nullopt, 0.0);
    for (int i = 0; i < 3; ++i) writer.record(img, all[static_cast<std::size_t>(i)]);
    writer.finish_interrupted(img);
  }
  fs::resize_file(path, fs::file_size(path) - 100);
  const app::SavedState first = app::read_state(path, settings_for(o), 150, 100);
  ASSERT_EQ(first.blocks.size(), 2u);
  {
    app::StateWriter writer(path, settings_for(o), first.valid_bytes);
    writer.record(img, all[9]);
    writer.finish_interrupted(img);
  }
  const app::SavedState second = app::read_state(path, settings_for(o), 150, 100);
  EXPECT_EQ(second.blocks, (std::vector<PixelRect>{all[0], all[1], all[9]}));
  EXPECT_EQ(second.valid_bytes, fs::file_size(path));
}

// The uninterrupted render leaves no state file; the continued one takes every saved block from the file (poisoned
// here, so a block rendered again would show) and renders the others exactly as the uninterrupted render did.
TEST(Continue, SavedBlocksAreTakenAndTheRestRenderedAsBefore) {
  const Scratch s;
  app::RenderOptions o = options_in(s);
  o.output = s.path() / "full.png";
  const app::JobResult full = run(o);
  ASSERT_EQ(full.exit_status, 0);
  EXPECT_EQ(names_in(s.path()), (std::set<std::string>{"full.png", "log.txt", "scene.pov"}));

  o.output = s.path() / "out.png";
  o.continue_trace = true;
  std::vector<PixelRect> saved;
  const std::vector<PixelRect> all = blocks_of(150, 100);
  for (std::size_t i = 0; i < all.size(); i += 2) saved.push_back(all[i]);
  image::Image poisoned = full.image;
  for (float& v : poisoned.rgba) v = 0.25f;
  write_state(o, poisoned, saved);
  const app::JobResult poisoned_result = run(o);
  ASSERT_EQ(poisoned_result.exit_status, 0);
  int wrong = 0;
  for (int y = 0; y < 100; ++y)
    for (int x = 0; x < 150; ++x) {
      bool in_saved = false;
      for (const PixelRect& b : saved) in_saved = in_saved || b.contains(x, y);
      for (int c = 0; c < 4; ++c) {
        const float want = in_saved ? 0.25f : full.image.pixel(x, y)[c];
        wrong += poisoned_result.image.pixel(x, y)[c] != want;
      }
    }
  EXPECT_EQ(wrong, 0);
  // The saved blocks (8 of the 15, a little over half the pixels) were not traced again.
  EXPECT_LT(poisoned_result.rays.camera * 10, full.rays.camera * 6);
  EXPECT_GT(poisoned_result.rays.camera * 10, full.rays.camera * 3);
  EXPECT_FALSE(fs::exists(s.path() / "out.povtrace-state")) << "the state file outlived the render";
  EXPECT_NE(read_file(s.path() / "log.txt").find("continuing from"), std::string::npos);

  // With the true pixels saved, the file is byte for byte the uninterrupted render's.
  fs::remove(s.path() / "out.png");
  write_state(o, full.image, saved);
  const app::JobResult continued = run(o);
  EXPECT_TRUE(same_pixels(continued.image, full.image));
  EXPECT_EQ(read_file(s.path() / "out.png"), read_file(s.path() / "full.png"));
}

// A crash mid-write leaves a partial last record: the intact records before it are used, and the continued
// render appends after them (the damaged tail is cut off, not left between records).
TEST(Continue, ADamagedTailCostsOnlyItsBlock) {
  const Scratch s;
  app::RenderOptions o = options_in(s);
  const app::JobResult full = run(o);
  ASSERT_EQ(full.exit_status, 0);
  const std::string full_png = read_file(s.path() / "out.png");
  fs::remove(s.path() / "out.png");

  const std::vector<PixelRect> all = blocks_of(150, 100);
  const std::vector<PixelRect> saved(all.begin(), all.begin() + 5);
  write_state(o, full.image, saved);
  const fs::path state = s.path() / "out.povtrace-state";
  fs::resize_file(state, fs::file_size(state) - 100);
  const app::SavedState read = app::read_state(state, settings_for(o), 150, 100);
  ASSERT_EQ(read.status, Status::usable);
  EXPECT_EQ(read.blocks, std::vector<PixelRect>(saved.begin(), saved.begin() + 4));

  // One flipped byte inside a record's pixels: that record and those after it are dropped.
  write_state(o, full.image, saved);
  std::string bytes = read_file(state);
  // Records are 28 bytes of tag, corners and checksum plus 16 bytes a pixel; the last one is 22 pixels wide.
  bytes[bytes.size() - (22 * 32 * 16 + 28) - 2 * (32 * 32 * 16 + 28) + 100] ^= 0x40;   // in the third from the end
  write_file(state, bytes);
  EXPECT_EQ(app::read_state(state, settings_for(o), 150, 100).blocks.size(), 2u);

  o.continue_trace = true;
  const app::JobResult continued = run(o);
  ASSERT_EQ(continued.exit_status, 0);
  EXPECT_EQ(read_file(s.path() / "out.png"), full_png);
  EXPECT_FALSE(fs::exists(state));
}

// A state file from another render: refused (exit 2) naming the first difference, nothing written, the state file
// left as it was for the render it belongs to.
TEST(Continue, AStateFileFromOtherSettingsIsRefused) {
  const Scratch s;
  app::RenderOptions o = options_in(s);
  o.continue_trace = true;
  image::Image blank(150, 100);
  write_state(o, blank, {blocks_of(150, 100)[0]});
  const fs::path state = s.path() / "out.povtrace-state";
  const std::string before = read_file(state);

  app::RenderOptions wider = o;
  wider.width = 160;
  try {
    run(wider);
    ADD_FAILURE() << "a state file of another width was accepted";
  } catch (const app::UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("Width: 150 in the state file, 160 now"), std::string::npos) << e.what();
  }
  app::RenderOptions other_aa = o;
  other_aa.antialias_threshold = 0.1;
  try {
    run(other_aa);
    ADD_FAILURE() << "a state file of another antialiasing threshold was accepted";
  } catch (const app::UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("Antialias_Threshold"), std::string::npos) << e.what();
  }
  // The scene file changed since.
  write_file(o.input, read_file(o.input) + "\n// edited\n");
  try {
    run(o);
    ADD_FAILURE() << "a state file of another scene text was accepted";
  } catch (const app::UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("scene: "), std::string::npos) << e.what();
  }
  EXPECT_EQ(read_file(state), before);
  EXPECT_FALSE(fs::exists(s.path() / "out.png"));
}

// The #include files count as the scene: a state file of the same scene text with an edited include is refused.
TEST(Continue, AnEditedIncludeFileIsAnotherScene) {
  const Scratch s;
  app::RenderOptions o = options_in(s);
  write_file(s.path() / "part.inc", "sphere { <0.5, 0.5, -1>, 0.2 pigment { rgb <0, 0, 1> } }\n");
  write_file(o.input, read_file(o.input) + "\n#include \"part.inc\"\n");
  o.library_paths = {s.path()};
  o.continue_trace = true;
  const SceneDescription parsed = parse_scene(o.input, app::parse_options_from(o));
  const std::string settings = app::state_settings(o, app::plan_frames(o.animation).at(0), std::nullopt, 32,
                                                   read_text_file(o.input), parsed.file_names->all());
  EXPECT_NE(settings.find("part.inc="), std::string::npos) << settings;
  image::Image blank(150, 100);
  auto save = [&] {
    app::StateWriter writer(s.path() / "out.povtrace-state", settings, std::nullopt, 0.0);
    writer.record(blank, blocks_of(150, 100)[0]);
    writer.finish_interrupted(blank);
  };
  save();
  EXPECT_EQ(run(o).exit_status, 0);   // the same files: continued
  EXPECT_NE(read_file(s.path() / "log.txt").find("continuing from"), std::string::npos);
  fs::remove(s.path() / "out.png");
  save();
  write_file(s.path() / "part.inc", "sphere { <0.5, 0.5, -1>, 0.3 pigment { rgb <0, 0, 1> } }\n");
  try {
    run(o);
    ADD_FAILURE() << "a state file of another include file was accepted";
  } catch (const app::UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("part.inc"), std::string::npos) << e.what();
  }
}

// Not a povtrace state file (POV-Ray: a bad header means "start over"): a warning, a render from the start.
TEST(Continue, AForeignFileIsNotUsedAndTheRenderStartsOver) {
  const Scratch s;
  app::RenderOptions o = options_in(s);
  o.output = s.path() / "full.png";
  ASSERT_EQ(run(o).exit_status, 0);
  o.output = s.path() / "out.png";
  o.continue_trace = true;
  for (const std::string& junk : {std::string("POV-Ray render state, not ours\n"), std::string(),
                                  std::string("povtrace render state 1\n999999999\nshort")}) {
    write_file(s.path() / "out.povtrace-state", junk);
    EXPECT_EQ(app::read_state(s.path() / "out.povtrace-state", settings_for(o), 150, 100).status, Status::unreadable);
    ASSERT_EQ(run(o).exit_status, 0);
    EXPECT_EQ(read_file(s.path() / "out.png"), read_file(s.path() / "full.png"));
    EXPECT_NE(read_file(s.path() / "log.txt").find("is not a povtrace render state file"), std::string::npos);
    EXPECT_FALSE(fs::exists(s.path() / "out.povtrace-state"));
    fs::remove(s.path() / "out.png");
  }
}

// POV-Ray 3.7: +C with a non-empty output file (and here: no state file to continue) renders nothing; an empty
// file, or none, is rendered from the start.
TEST(Continue, ANonEmptyOutputFileIsAlreadyRendered) {
  const Scratch s;
  app::RenderOptions o = options_in(s);
  o.continue_trace = true;
  write_file(s.path() / "out.png", "an earlier image");
  const app::JobResult skipped = run(o);
  EXPECT_EQ(skipped.exit_status, 0);
  EXPECT_TRUE(skipped.skipped);
  EXPECT_EQ(read_file(s.path() / "out.png"), "an earlier image");
  EXPECT_NE(read_file(s.path() / "log.txt").find("already rendered"), std::string::npos);
  EXPECT_EQ(names_in(s.path()), (std::set<std::string>{"out.png", "log.txt", "scene.pov"}));

  write_file(s.path() / "out.png", "");
  const app::JobResult rendered = run(o);
  EXPECT_FALSE(rendered.skipped);
  EXPECT_GT(fs::file_size(s.path() / "out.png"), 100u);

  fs::remove(s.path() / "out.png");
  EXPECT_FALSE(run(o).skipped);
  EXPECT_NE(read_file(s.path() / "log.txt").find("no render state file"), std::string::npos);
  EXPECT_EQ(names_in(s.path()), (std::set<std::string>{"out.png", "log.txt", "scene.pov"}));
}

// An interrupted render's state file wins over an older output file: povtrace (unlike POV-Ray) keeps the old
// image while a new render runs, so the old file does not mean "rendered".
TEST(Continue, AStateFileIsContinuedEvenIfAnOldOutputFileExists) {
  const Scratch s;
  app::RenderOptions o = options_in(s);
  const app::JobResult full = run(o);
  const std::string full_png = read_file(s.path() / "out.png");
  write_file(s.path() / "out.png", "an image from before");
  o.continue_trace = true;
  write_state(o, full.image, {blocks_of(150, 100)[3]});
  const app::JobResult continued = run(o);
  EXPECT_FALSE(continued.skipped);
  EXPECT_EQ(read_file(s.path() / "out.png"), full_png);
}

TEST(Continue, StandardOutputCannotBeContinued) {
  const Scratch s;
  app::RenderOptions o = options_in(s);
  o.output = "-";
  o.continue_trace = true;
  EXPECT_THROW(run(o), app::UsageError);
}

// -F writes no image, so no state file either (as POV-Ray); +C then just renders.
TEST(Continue, NoStateFileWithoutAnOutputFile) {
  const Scratch s;
  app::RenderOptions o = options_in(s);
  o.write_file = false;
  o.continue_trace = true;
  EXPECT_EQ(run(o).exit_status, 0);
  EXPECT_EQ(names_in(s.path()), (std::set<std::string>{"log.txt", "scene.pov"}));
}

// An animation under +C: frames whose file exists are skipped (parsed, as POV-Ray, but not rendered or written),
// the others rendered; a frame's state file continues that frame only.
TEST(Continue, AnAnimationSkipsFramesAlreadyWritten) {
  const Scratch s;
  app::RenderOptions o = options_in(s);
  write_file(o.input, read_file(o.input) + "\nsphere { <clock * 2 - 1, 0, -1>, 0.3 pigment { rgb <0, 1, 0> } }\n");
  o.width = 80;
  o.height = 60;
  o.output = s.path() / "a.png";
  o.animation.initial_frame = 1;
  o.animation.final_frame = 3;
  ASSERT_EQ(run(o).frames, 3);
  const std::string a1 = read_file(s.path() / "a1.png"), a2 = read_file(s.path() / "a2.png"),
                    a3 = read_file(s.path() / "a3.png");
  EXPECT_NE(a1, a2);

  write_file(s.path() / "a1.png", "kept");
  fs::remove(s.path() / "a2.png");
  fs::remove(s.path() / "a3.png");
  // Frame 3 was interrupted after two blocks (its state file holds them, poisoned so their use shows).
  {
    app::RenderOptions frame3 = o;
    frame3.animation.subset_start = 3;
    frame3.animation.subset_end = 3;
    frame3.write_file = false;
    const app::JobResult r3 = run(frame3);
    image::Image poisoned = r3.image;
    for (float& v : poisoned.rgba) v = 0.5f;
    const app::FramePlan plan = app::plan_frames(o.animation);
    app::StateWriter writer(s.path() / "a3.povtrace-state",
                            app::state_settings(o, plan.at(2), std::nullopt, 32, read_text_file(o.input)),
                            std::nullopt);
    writer.record(poisoned, {0, 0, 31, 31});   // only noted: the default delay has not passed
    EXPECT_FALSE(fs::exists(s.path() / "a3.povtrace-state"));
    writer.record(poisoned, {32, 32, 63, 59});
    writer.finish_interrupted(poisoned);
  }
  o.continue_trace = true;
  const app::JobResult r = run(o);
  EXPECT_EQ(r.exit_status, 0);
  EXPECT_EQ(r.frames, 2);
  EXPECT_EQ(read_file(s.path() / "a1.png"), "kept");
  EXPECT_EQ(read_file(s.path() / "a2.png"), a2);
  EXPECT_EQ(r.image.pixel(40, 40)[0], 0.5f) << "frame 3's saved block was not used";
  EXPECT_NE(r.image.pixel(70, 5)[0], 0.5f);
  EXPECT_EQ(names_in(s.path()), (std::set<std::string>{"a1.png", "a2.png", "a3.png", "log.txt", "scene.pov"}));
}

}  // namespace
