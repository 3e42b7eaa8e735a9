// Ctrl-C (issue 7): SIGINT during a render stops povtrace promptly with exit status 1, leaves an existing output
// file byte for byte as it was, creates none when there was none, and leaves no temporary file behind; only the
// render state file of the finished blocks (issue 18, +C). The test runs the real program (POVTRACE_EXE) on a
// scene that takes several seconds, and signals it once it reports progress, i.e. once it is rendering; and on a
// scene whose parse never ends, which Ctrl-C must stop too. Then +C continues the interrupted render (a still and
// an animation) to the same bytes as an uninterrupted render.

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

extern char** environ;

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

// Twelve reflective spheres under a 9×9 area light, every pixel supersampled (+A0.0 +R3): about 15 s at 640×480 on
// one core of the machine this was written on, and bounded (no recursion beyond max_trace_level).
constexpr const char* kSlowScene = R"(#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -6> look_at <0, 0.6, 0> }
light_source { <-4, 8, -5> color rgb 1 area_light <3, 0, 0>, <0, 0, 3>, 9, 9 }
plane { y, 0 pigment { checker rgb 0.9 rgb 0.3 } }
#declare I = 0;
#while (I < 12)
  sphere { <mod(I, 4) * 1.2 - 1.8, 0.4, div(I, 4) * 1.2 - 1>, 0.4
    pigment { rgb <0.8, 0.4, 0.2> } finish { phong 0.5 reflection 0.2 } }
  #declare I = I + 1;
#end
)";

// Generous limits: the machine is shared and noisy. "Promptly" means within one render block of the signal; 20 s
// is far above that and far below the render's own length on any machine slow enough to need it.
constexpr auto kStartLimit = std::chrono::seconds(120);   // until the first progress line
constexpr auto kStopLimit = std::chrono::seconds(20);     // from SIGINT to exit

// A folder of its own for each test, removed afterwards.
class ScratchFolder {
 public:
  ScratchFolder() {
    std::string pattern = (fs::temp_directory_path() / "povtrace_interrupt_XXXXXX").string();
    if (!::mkdtemp(pattern.data())) throw std::runtime_error("mkdtemp failed");
    path_ = pattern;
  }
  ~ScratchFolder() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

void write_file(const fs::path& p, const std::string& bytes) {
  std::ofstream out(p, std::ios::binary);
  out << bytes;
}

std::string read_file(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::set<std::string> names_in(const fs::path& folder) {
  std::set<std::string> names;
  for (const auto& entry : fs::directory_iterator(folder)) names.insert(entry.path().filename().string());
  return names;
}

// povtrace running with its stderr on a pipe.
class RunningRender {
 public:
  explicit RunningRender(const std::vector<std::string>& args) {
    int fds[2];
    if (::pipe(fds) != 0) throw std::runtime_error("pipe failed");
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, fds[1], STDERR_FILENO);
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addclose(&actions, fds[0]);
    posix_spawn_file_actions_addclose(&actions, fds[1]);
    std::vector<char*> argv;
    std::vector<std::string> storage{POVTRACE_EXE};
    storage.insert(storage.end(), args.begin(), args.end());
    for (std::string& a : storage) argv.push_back(a.data());
    argv.push_back(nullptr);
    const int failed = posix_spawn(&pid_, POVTRACE_EXE, &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    ::close(fds[1]);
    stderr_fd_ = fds[0];
    if (failed != 0) throw std::runtime_error("cannot start " + std::string(POVTRACE_EXE));
  }
  ~RunningRender() {
    if (pid_ > 0 && !status_) {   // a failed test must not leave the render running
      ::kill(pid_, SIGKILL);
      int ignored = 0;
      ::waitpid(pid_, &ignored, 0);
    }
    ::close(stderr_fd_);
  }

  // Reads stderr until `text` appears (at or after offset `from`); false at end of output or after `limit`.
  bool wait_for_line(const std::string& text, Clock::duration limit, std::size_t from = 0) {
    const auto deadline = Clock::now() + limit;
    while (Clock::now() < deadline) {
      if (output_.find(text, from) != std::string::npos) return true;
      if (!read_some(deadline)) return false;
    }
    return output_.find(text, from) != std::string::npos;
  }

  // The exit status once the process has ended, or nothing if it is still running after `limit`.
  std::optional<int> wait_for_exit(Clock::duration limit) {
    const auto deadline = Clock::now() + limit;
    while (Clock::now() < deadline) {
      int status = 0;
      if (::waitpid(pid_, &status, WNOHANG) == pid_) {
        status_ = status;
        while (read_some(Clock::now() + std::chrono::seconds(1))) {
        }
        return status;
      }
      read_some(Clock::now() + std::chrono::milliseconds(50));
    }
    return std::nullopt;
  }

  void signal(int sig) const { ::kill(pid_, sig); }
  const std::string& output() const { return output_; }

 private:
  // One read from stderr, waiting until `deadline`; false at end of output (or if nothing came in time).
  bool read_some(Clock::time_point deadline) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
    pollfd p{stderr_fd_, POLLIN, 0};
    if (::poll(&p, 1, static_cast<int>(std::max<long long>(left, 0))) <= 0) return false;
    char buf[4096];
    const ssize_t n = ::read(stderr_fd_, buf, sizeof buf);
    if (n <= 0) return false;
    output_.append(buf, static_cast<std::size_t>(n));
    return true;
  }

  pid_t pid_ = -1;
  int stderr_fd_ = -1;
  std::string output_;
  std::optional<int> status_;
};

// After SIGINT (or SIGTERM): povtrace exits by itself with status 1 within kStopLimit and says why (`message`).
void expect_interrupted(RunningRender& render, const std::string& message) {
  const std::optional<int> status = render.wait_for_exit(kStopLimit);
  ASSERT_TRUE(status.has_value()) << "povtrace still running 20 s after the signal:\n" << render.output();
  ASSERT_TRUE(WIFEXITED(*status)) << "povtrace did not exit normally (killed by a signal?):\n" << render.output();
  EXPECT_EQ(WEXITSTATUS(*status), 1) << render.output();
  EXPECT_NE(render.output().find(message), std::string::npos) << render.output();
}

// Starts the slow render into `output`, waits until it reports progress, sends SIGINT and checks how it ends.
void interrupt_render(const fs::path& folder, const fs::path& output) {
  const fs::path scene = folder / "slow.pov";
  write_file(scene, kSlowScene);
  RunningRender render({"-D", "+W640", "+H480", "+A0.0", "+R3", "+FE", "+O" + output.string(), scene.string()});
  ASSERT_TRUE(render.wait_for_line("povtrace: rendering", kStartLimit))
      << "no progress line from povtrace:\n" << render.output();
  render.signal(SIGINT);
  expect_interrupted(render, "povtrace: interrupted; no image written");
}

TEST(Interrupt, SigintKeepsAnExistingOutputFileAsItWas) {
  const ScratchFolder folder;
  const fs::path output = folder.path() / "out.exr";
  using namespace std::string_literals;
  const std::string old_bytes = "an image from an earlier render\n\x00\x01\xff"s;   // NUL included
  write_file(output, old_bytes);
  interrupt_render(folder.path(), output);
  EXPECT_EQ(read_file(output), old_bytes);
  EXPECT_EQ(names_in(folder.path()), (std::set<std::string>{"out.exr", "out.povtrace-state", "slow.pov"}))
      << "a temporary file was left behind";
}

TEST(Interrupt, SigintCreatesNoOutputFile) {
  const ScratchFolder folder;
  const fs::path output = folder.path() / "out.exr";
  interrupt_render(folder.path(), output);
  EXPECT_FALSE(fs::exists(output));
  EXPECT_EQ(names_in(folder.path()), (std::set<std::string>{"out.povtrace-state", "slow.pov"}))
      << "a file was left behind";
}

}  // namespace

namespace {

// A parse that never ends (POV-Ray runs an endless #while forever, and so does povtrace) must still stop on Ctrl-C,
// with a located error, and leave the existing output file alone.
TEST(Interrupt, SigintStopsAnEndlessParse) {
  const ScratchFolder folder;
  const fs::path output = folder.path() / "out.exr";
  const std::string old_bytes = "an image from an earlier render\n";
  write_file(output, old_bytes);
  const fs::path scene = folder.path() / "endless.pov";
  write_file(scene, "#version 3.7;\n#declare I = 0;\n#while (1) #declare I = I + 1; #end\n");
  RunningRender render({"-D", "+W64", "+H48", "+FE", "+O" + output.string(), scene.string()});
  // Nothing is printed while parsing, so a fixed delay stands for "it is parsing": povtrace installs its handler
  // within milliseconds of starting, and the loop never ends, so any delay lands inside the parse.
  std::this_thread::sleep_for(std::chrono::milliseconds(1500));
  render.signal(SIGINT);
  expect_interrupted(render, "error: interrupted while parsing");
  EXPECT_EQ(read_file(output), old_bytes);
  EXPECT_EQ(names_in(folder.path()), (std::set<std::string>{"endless.pov", "out.exr"})) << "a file was left behind";
}

}  // namespace

namespace {

// povtrace run to its end; its exit status (0 expected) and stderr.
int run_to_end(const std::vector<std::string>& args, std::string* output = nullptr) {
  RunningRender render(args);
  const std::optional<int> status = render.wait_for_exit(std::chrono::minutes(5));
  if (output) *output = render.output();
  if (!status || !WIFEXITED(*status)) return -1;
  return WEXITSTATUS(*status);
}

// The slow scene at 320 × 240 with method 1 antialiasing and jitter (about 6 s on 2 cores): interrupted once it
// reports progress, continued with +C; the file equals an uninterrupted render's byte for byte, and the state file
// is gone afterwards.
TEST(Interrupt, ContinueGivesTheBytesOfAnUninterruptedRender) {
  const ScratchFolder folder;
  const fs::path scene = folder.path() / "slow.pov";
  write_file(scene, kSlowScene);
  const std::vector<std::string> args = {"--no-povray-ini", "-D", "+W320", "+H240", "+A0.0", "+R3", "+FE",
                                         scene.string()};
  auto with = [&](std::vector<std::string> extra) {
    std::vector<std::string> all = args;
    all.insert(all.end(), extra.begin(), extra.end());
    return all;
  };
  const fs::path part = folder.path() / "part.exr", state = folder.path() / "part.povtrace-state";
  {
    RunningRender render(with({"+O" + part.string()}));
    ASSERT_TRUE(render.wait_for_line("povtrace: rendering", kStartLimit)) << render.output();
    render.signal(SIGINT);
    expect_interrupted(render, "+C continues the render");
  }
  ASSERT_FALSE(fs::exists(part));
  ASSERT_TRUE(fs::exists(state));
  std::string log;
  ASSERT_EQ(run_to_end(with({"+C", "+O" + part.string()}), &log), 0) << log;
  EXPECT_NE(log.find("continuing from"), std::string::npos) << log;
  EXPECT_FALSE(fs::exists(state));

  const fs::path full = folder.path() / "full.exr";
  ASSERT_EQ(run_to_end(with({"+O" + full.string()}), &log), 0) << log;
  EXPECT_EQ(read_file(part), read_file(full)) << "the continued render differs from the uninterrupted one";
  EXPECT_EQ(names_in(folder.path()), (std::set<std::string>{"full.exr", "part.exr", "slow.pov"}));

  // +C once more: the file exists and no state says otherwise, so it is "already rendered" (POV-Ray's rule).
  const auto written = fs::last_write_time(part);
  ASSERT_EQ(run_to_end(with({"+C", "+O" + part.string()}), &log), 0) << log;
  EXPECT_NE(log.find("already rendered"), std::string::npos) << log;
  EXPECT_EQ(fs::last_write_time(part), written);
}

// An animation of three frames interrupted (SIGTERM this time) in frame 2: frame 1 is written, frame 2 has a state
// file. +C skips
// frame 1 (its file exists), continues frame 2 and renders frame 3; frame 2 equals an uninterrupted render of it.
TEST(Interrupt, ContinueAnInterruptedAnimation) {
  const ScratchFolder folder;
  const fs::path scene = folder.path() / "slow.pov";
  write_file(scene, std::string(kSlowScene) + "sphere { <clock * 4 - 2, 1.5, 0>, 0.3 pigment { rgb 1 } }\n");
  // Frames must take over a second, so that frame 2 prints a progress line before it is interrupted (0.8 s each at
  // 240x180 on an idle machine of this project's kind: too short).
  const std::vector<std::string> args = {"--no-povray-ini", "-D", "+W400", "+H300", "+A0.0", "+R3", "+FE",
                                         "+KFI1", "+KFF3", scene.string()};
  auto with = [&](std::vector<std::string> extra) {
    std::vector<std::string> all = args;
    all.insert(all.end(), extra.begin(), extra.end());
    return all;
  };
  const fs::path out = folder.path() / "a.exr";
  {
    RunningRender render(with({"+O" + out.string()}));
    ASSERT_TRUE(render.wait_for_line("povtrace: frame 2", kStartLimit)) << render.output();
    // Frame 2's first progress line (frame 1's come before the frame 2 note).
    ASSERT_TRUE(render.wait_for_line("povtrace: rendering", kStartLimit, render.output().find("povtrace: frame 2")))
        << render.output();
    ASSERT_EQ(render.output().find("povtrace: frame 3"), std::string::npos) << "frame 2 ended too soon";
    render.signal(SIGTERM);
    expect_interrupted(render, "+C continues the render");
  }
  ASSERT_TRUE(fs::exists(folder.path() / "a1.exr"));
  ASSERT_FALSE(fs::exists(folder.path() / "a2.exr"));
  ASSERT_TRUE(fs::exists(folder.path() / "a2.povtrace-state"));
  const std::string a1 = read_file(folder.path() / "a1.exr");
  const auto a1_written = fs::last_write_time(folder.path() / "a1.exr");

  std::string log;
  ASSERT_EQ(run_to_end(with({"+C", "+O" + out.string()}), &log), 0) << log;
  EXPECT_NE(log.find("a1.exr' is already rendered"), std::string::npos) << log;
  EXPECT_NE(log.find("continuing from"), std::string::npos) << log;
  EXPECT_EQ(fs::last_write_time(folder.path() / "a1.exr"), a1_written);
  EXPECT_EQ(names_in(folder.path()), (std::set<std::string>{"a1.exr", "a2.exr", "a3.exr", "slow.pov"}));

  // Frame 2 alone, uninterrupted (Subset_Start/End_Frame keep the numbering and the clock).
  const fs::path ref = folder.path() / "ref.exr";
  ASSERT_EQ(run_to_end(with({"+SF2", "+EF2", "+O" + ref.string()}), &log), 0) << log;
  EXPECT_EQ(read_file(folder.path() / "a2.exr"), read_file(folder.path() / "ref2.exr"));
}

}  // namespace
