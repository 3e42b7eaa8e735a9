// Tests of the shell-out commands (app/shellouts.*) and the message streams (app/messages.*).

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "app/messages.hpp"
#include "app/shellouts.hpp"

namespace povtrace::app {
namespace {

namespace fs = std::filesystem;

ShellContext context() {
  ShellContext c;
  c.output = "out/x.png";
  c.scene = "ball";
  c.frame = 7;
  c.clock = 0.25;
  c.width = 320;
  c.height = 240;
  return c;
}

TEST(ShellCodes, ExpandAsPovray) {
  EXPECT_EQ(expand_shell_codes("cmd %o %s %n %k %h %w 100%% %q %", context()),
            "cmd out/x.png ball 7 0.250000 240 320 100% %q %");
  EXPECT_EQ(expand_shell_codes("plain", context()), "plain");
}

TEST(ShellAction, ReturnActions) {
  ShellCommand c;
  c.command = "x";
  EXPECT_EQ(shell_action(c, 1), ShellAction::proceed);   // i: ignore
  const std::pair<char, ShellAction> actions[] = {{'s', ShellAction::skip_frame}, {'a', ShellAction::skip_all},
                                                  {'q', ShellAction::quit},       {'u', ShellAction::user_abort},
                                                  {'f', ShellAction::fatal_error}};
  for (const auto& [letter, action] : actions) {
    c.action = letter;
    c.negate = false;
    EXPECT_EQ(shell_action(c, 0), ShellAction::proceed) << letter;
    EXPECT_EQ(shell_action(c, 3), action) << letter;
    c.negate = true;
    EXPECT_EQ(shell_action(c, 0), action) << letter;
    EXPECT_EQ(shell_action(c, 3), ShellAction::proceed) << letter;
  }
}

RenderOptions with_command(const std::string& command, char action, bool allowed) {
  RenderOptions o;
  o.shell_commands.pre_scene.command = command;
  o.shell_commands.pre_scene.action = action;
  o.allow_shellout = allowed;
  return o;
}

TEST(ShellOuts, RunOnlyWhenAllowed) {
  const fs::path marker = fs::temp_directory_path() / ("povtrace_shellout_" + std::to_string(::getpid()));
  fs::remove(marker);
  std::vector<std::string> notes;
  auto warn = [&](const std::string& n) { notes.push_back(n); };
  const std::string touch = "echo %s %w > '" + marker.string() + "'";

  ShellOuts refused(with_command(touch, 'f', false), warn);
  EXPECT_EQ(refused.run(ShellEvent::pre_scene, context()), ShellAction::proceed);
  EXPECT_EQ(refused.run(ShellEvent::pre_scene, context()), ShellAction::proceed);
  EXPECT_FALSE(fs::exists(marker));
  ASSERT_EQ(notes.size(), 1u);   // one note per command and run
  EXPECT_NE(notes[0].find("Pre_Scene_Command was not run"), std::string::npos);
  EXPECT_NE(notes[0].find("--allow-shellout"), std::string::npos);

  ShellOuts allowed(with_command(touch, 'f', true), warn);
  EXPECT_EQ(allowed.run(ShellEvent::pre_scene, context()), ShellAction::proceed);
  std::ifstream in(marker);
  std::string text;
  std::getline(in, text);
  EXPECT_EQ(text, "ball 320");
  fs::remove(marker);

  EXPECT_EQ(ShellOuts(with_command("false", 'q', true), warn).run(ShellEvent::pre_scene, context()),
            ShellAction::quit);
  EXPECT_EQ(ShellOuts(with_command("true", 'q', true), warn).run(ShellEvent::pre_scene, context()),
            ShellAction::proceed);
  EXPECT_EQ(ShellOuts(with_command("exit 3", 'f', true), warn).run(ShellEvent::pre_scene, context()),
            ShellAction::fatal_error);
  // Events without a command do nothing.
  EXPECT_EQ(ShellOuts(with_command("false", 'q', true), warn).run(ShellEvent::post_frame, context()),
            ShellAction::proceed);
}

std::string read(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(Messages, FilesPerStreamAllFileAndAppend) {
  const fs::path dir = fs::temp_directory_path() / ("povtrace_messages_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  MessageStreams s;
  s.debug.console = s.warning.console = s.statistics.console = false;
  s.debug.file = dir / "debug.log";
  s.warning.file = dir / "warning.log";
  s.all_file = dir / "all.log";
  {
    Messages m(s);
    m.write(Stream::debug, "dbg ");
    m.write(Stream::debug, "text\n");
    m.write(Stream::warning, "w1");
    m.write(Stream::statistics, "stats");
    EXPECT_FALSE(m.console(Stream::debug));
    EXPECT_TRUE(m.console(Stream::fatal));
  }
  EXPECT_EQ(read(dir / "debug.log"), "dbg text\n");
  EXPECT_EQ(read(dir / "warning.log"), "w1\n");
  EXPECT_EQ(read(dir / "all.log"), "dbg text\nw1\nstats\n");
  {
    Messages again(s);   // replaced
    again.write(Stream::warning, "w2");
  }
  EXPECT_EQ(read(dir / "warning.log"), "w2\n");
  s.append = true;
  {
    Messages appending(s);
    appending.write(Stream::warning, "w3");
  }
  EXPECT_EQ(read(dir / "warning.log"), "w2\nw3\n");
  s.fatal.file = dir / "no" / "such" / "dir" / "f.log";
  EXPECT_THROW(Messages bad(s), std::runtime_error);
  fs::remove_all(dir);
}


// #debug text reaches the debug stream a complete line at a time, as POV-Ray 3.7's parser sends it: '\r' ends a
// line too, and what follows the last line end is dropped (checked against povray 3.7.0.10: a scene's final
// `#debug "tail"` appears neither on the console nor in the +GD file).
TEST(Messages, DebugTextCompleteLinesOnly) {
  const fs::path dir = fs::temp_directory_path() / ("povtrace_debuglines_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  MessageStreams s;
  s.debug.console = false;
  s.debug.file = dir / "debug.txt";
  {
    Messages m(s);
    DebugLines frame1(m);
    frame1.add("\nGenerated the file: a1.html");
    frame1.add("\nGenerated the file: a2.html");   // never ended: dropped with the frame's parse
    DebugLines frame2(m);
    frame2.add("x=");
    frame2.add("1\n");
    frame2.add("a\rb\n");
    frame2.add("\n");
  }
  EXPECT_EQ(read(dir / "debug.txt"), "\nGenerated the file: a1.html\nx=1\na\nb\n\n");
  fs::remove_all(dir);
}

}  // namespace
}  // namespace povtrace::app
