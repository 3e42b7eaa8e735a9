// povtrace: renders a POV-Ray scene file. Exit status 0 on success, 1 for a bad scene or a failed render
// (message with file:line:column), 2 for a bad command line. No output file is created or touched unless the
// render completes: images are written to a temporary file and renamed. An interrupted render leaves the state file
// of its finished blocks for +C (app/render_state.hpp).
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "app/assemble.hpp"
#include "app/messages.hpp"
#include "app/options.hpp"
#ifdef POVTRACE_HAVE_MPI
#include "app/mpi_render.hpp"
#endif
#include "app/render_job.hpp"
#include "app/shellouts.hpp"
#include "scene/source.hpp"
#include "renderer/image/image.hpp"

namespace {
std::atomic<bool> g_interrupted{false};
extern "C" void on_interrupt(int) { g_interrupted = true; }

// Create_Ini: the resolved settings, written before the render (as povray does).
void create_ini(const povtrace::app::RenderOptions& options) {
  std::ofstream out(*options.create_ini);
  out << povtrace::app::ini_text(options);
  if (!out) throw povtrace::app::UsageError("cannot write the Create_Ini file '" + options.create_ini->string() + "'");
}
}  // namespace

int main(int argc, char** argv) {
  using namespace povtrace;
  if (argc >= 2 && std::string(argv[1]) == "--assemble") {
    try {
      return app::run_assemble(std::vector<std::string>(argv + 2, argv + argc));
    } catch (const app::UsageError& e) {
      std::cerr << "povtrace: " << e.what() << "\nTry 'povtrace --help'.\n";
      return 2;
    } catch (const std::exception& e) {
      std::cerr << "povtrace: --assemble: " << e.what() << "\n";
      return 1;
    }
  }
  app::RenderOptions options;
  std::optional<app::Messages> messages;
  try {
    const app::IniEnvironment environment = app::process_environment();
    options = app::parse_command_line(argc, argv, &environment);
    if (options.help || options.version || options.print != app::RenderOptions::Print::nothing) {
      std::cout << (options.help      ? app::usage_text()
                    : options.version ? app::version_text()
                    : options.print == app::RenderOptions::Print::man_page ? app::man_page()
                                                                           : app::switch_table_markdown());
      return 0;
    }
    messages.emplace(options.streams);
    if (options.create_ini) create_ini(options);
  } catch (const app::UsageError& e) {
    std::cerr << "povtrace: " << e.what() << "\nTry 'povtrace --help'.\n";
    return 2;
  } catch (const std::runtime_error& e) {   // a message file that cannot be opened
    std::cerr << "povtrace: " << e.what() << "\n";
    return 2;
  }
  for (const std::string& w : options.warnings) messages->write(app::Stream::warning, "povtrace: warning: " + w);
  if (options.input.empty()) {
    messages->write(app::Stream::fatal, "povtrace: no scene file given\nTry 'povtrace --help'.");
    return 2;
  }
  app::ShellOuts shellouts(options, [&](const std::string& w) {
    messages->write(app::Stream::warning, "povtrace: warning: " + w);
  });
  const app::ShellContext context =
      app::ShellOuts::context_for(options, options.write_file ? app::resolved_output_path(options).string() : "");
  // Fatal_Error_Command after the message; its return action cannot make things worse than an error.
  auto fatal = [&](const std::string& text) {
    messages->write(app::Stream::fatal, text);
    shellouts.run(app::ShellEvent::fatal_error, context);
    return 1;
  };
  std::signal(SIGINT, on_interrupt);
  std::signal(SIGTERM, on_interrupt);
  try {
    if (options.vs_povray) return app::run_vs_povray(options, g_interrupted);
#ifdef POVTRACE_HAVE_MPI
    if (app::mpi_launched()) return app::run_mpi_render(options, g_interrupted);   // started by mpirun, N > 1
#endif
    const int status = app::run_render(options, g_interrupted, &*messages).exit_status;
    if (g_interrupted) {
      const app::ShellAction action = shellouts.run(app::ShellEvent::user_abort, context);
      if (action == app::ShellAction::fatal_error) return fatal("povtrace: User_Abort_Command failed");
    }
    return status;
  } catch (const app::UsageError& e) {   // found once the render starts, e.g. a region outside the image
    std::cerr << "povtrace: " << e.what() << "\nTry 'povtrace --help'.\n";
    return 2;
  } catch (const ParseError& e) {
    return fatal(e.what());
  } catch (const image::ImageError& e) {
    return fatal(std::string("povtrace: ") + e.what());
  } catch (const std::exception& e) {
    return fatal(std::string("povtrace: error: ") + e.what());
  }
}
