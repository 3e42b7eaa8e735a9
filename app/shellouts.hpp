// POV-Ray's shell-out commands (Pre_Scene_Command … Fatal_Error_Command and their *_Return actions). povray on
// unix runs them only when povray.conf allows it; povtrace runs them only with --allow-shellout and otherwise
// reports, once per command, that it was not run.
#pragma once

#include <functional>
#include <string>

#include "app/options.hpp"

namespace povtrace::app {

enum class ShellEvent { pre_scene, post_scene, pre_frame, post_frame, user_abort, fatal_error };

// What the caller does next (POV-Ray's return actions): go on, skip this frame, skip the remaining frames,
// quit (stop, no error), act as on a user abort, act as on a fatal error.
enum class ShellAction { proceed, skip_frame, skip_all, quit, user_abort, fatal_error };

// The values of POV-Ray's % codes: %o output file, %s scene name without folder or extension, %n frame
// number, %k clock (six decimals), %h height, %w width, %% a percent sign.
struct ShellContext {
  std::string output;
  std::string scene;
  int frame = 0;
  double clock = 0.0;
  int width = 0;
  int height = 0;
};

// The command with its % codes expanded (unknown codes are kept as written).
std::string expand_shell_codes(const std::string& command, const ShellContext& context);

// The action a command's exit status asks for: the *_Return action when the command failed (exit status not 0;
// with '-' or '!', when it succeeded), otherwise proceed.
ShellAction shell_action(const ShellCommand& command, int exit_status);

class ShellOuts {
 public:
  // `warn` receives the "not run" notes (once per event) and the commands' failures to start.
  ShellOuts(const RenderOptions& options, std::function<void(const std::string&)> warn);

  // Runs the event's command, if one is set, through /bin/sh -c and returns the action its exit status asks
  // for; without --allow-shellout the command is not run and the result is proceed.
  ShellAction run(ShellEvent event, const ShellContext& context);

  // The context of a single render of `options` (frame 0, its clock).
  static ShellContext context_for(const RenderOptions& options, const std::string& output);

 private:
  const ShellCommands commands_;
  const bool allowed_;
  std::function<void(const std::string&)> warn_;
  bool warned_[6] = {};
};

}  // namespace povtrace::app
