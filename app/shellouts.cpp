#include "app/shellouts.hpp"

#include <spawn.h>
#include <sys/wait.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

extern char** environ;

namespace povtrace::app {
namespace {

const ShellCommand& command_of(const ShellCommands& c, ShellEvent e) {
  switch (e) {
    case ShellEvent::pre_scene: return c.pre_scene;
    case ShellEvent::post_scene: return c.post_scene;
    case ShellEvent::pre_frame: return c.pre_frame;
    case ShellEvent::post_frame: return c.post_frame;
    case ShellEvent::user_abort: return c.user_abort;
    case ShellEvent::fatal_error: return c.fatal_error;
  }
  return c.pre_scene;
}

const char* key_of(ShellEvent e) {
  constexpr const char* kKeys[] = {"Pre_Scene_Command", "Post_Scene_Command", "Pre_Frame_Command",
                                   "Post_Frame_Command", "User_Abort_Command", "Fatal_Error_Command"};
  return kKeys[static_cast<int>(e)];
}

// -1 when the shell cannot be started.
int run_shell(const std::string& command) {
  const char* argv[] = {"/bin/sh", "-c", command.c_str(), nullptr};
  pid_t pid = 0;
  if (posix_spawn(&pid, "/bin/sh", nullptr, nullptr, const_cast<char* const*>(argv), environ) != 0) return -1;
  int status = 0;
  while (waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) return -1;
  }
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  return 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
}

}  // namespace

std::string expand_shell_codes(const std::string& command, const ShellContext& c) {
  std::string out;
  for (std::size_t i = 0; i < command.size(); ++i) {
    if (command[i] != '%' || i + 1 == command.size()) {
      out += command[i];
      continue;
    }
    const char code = command[++i];
    char number[64];
    switch (code) {
      case '%': out += '%'; break;
      case 'o': out += c.output; break;
      case 's': out += c.scene; break;
      case 'n': out += std::to_string(c.frame); break;
      case 'k':
        std::snprintf(number, sizeof number, "%#.6f", c.clock);
        out += number;
        break;
      case 'h': out += std::to_string(c.height); break;
      case 'w': out += std::to_string(c.width); break;
      default:
        out += '%';
        out += code;
    }
  }
  return out;
}

ShellAction shell_action(const ShellCommand& command, int exit_status) {
  const bool failed = command.negate ? exit_status == 0 : exit_status != 0;
  if (!failed) return ShellAction::proceed;
  switch (command.action) {
    case 's': return ShellAction::skip_frame;
    case 'a': return ShellAction::skip_all;
    case 'q': return ShellAction::quit;
    case 'u': return ShellAction::user_abort;
    case 'f': return ShellAction::fatal_error;
    default: return ShellAction::proceed;
  }
}

ShellOuts::ShellOuts(const RenderOptions& options, std::function<void(const std::string&)> warn)
    : commands_(options.shell_commands), allowed_(options.allow_shellout), warn_(std::move(warn)) {}

ShellAction ShellOuts::run(ShellEvent event, const ShellContext& context) {
  const ShellCommand& command = command_of(commands_, event);
  if (command.command.empty()) return ShellAction::proceed;
  if (!allowed_) {
    bool& warned = warned_[static_cast<int>(event)];
    if (!warned && warn_) warn_(std::string(key_of(event)) + " was not run (give --allow-shellout to run it)");
    warned = true;
    return ShellAction::proceed;
  }
  const int status = run_shell(expand_shell_codes(command.command, context));
  if (status < 0 && warn_) warn_(std::string(key_of(event)) + ": cannot start /bin/sh");
  return shell_action(command, status < 0 ? 127 : status);
}

ShellContext ShellOuts::context_for(const RenderOptions& o, const std::string& output) {
  ShellContext c;
  c.output = output;
  c.scene = o.input.stem().string();
  c.clock = o.animation.clock.value_or(0.0);
  c.width = o.width;
  c.height = o.height;
  return c;
}

}  // namespace povtrace::app
