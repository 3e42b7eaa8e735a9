// povtrace: renders a POV-Ray scene file. Exit status 0 on success, 1 for a bad scene or a failed render
// (message with file:line:column), 2 for a bad command line. No output file is created or touched unless the
// render completes: images are written to a temporary file and renamed.
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

#include "app/assemble.hpp"
#include "app/options.hpp"
#ifdef POVTRACE_HAVE_MPI
#include "app/mpi_render.hpp"
#endif
#include "app/render_job.hpp"
#include "scene/source.hpp"
#include "renderer/image/image.hpp"

namespace {
std::atomic<bool> g_interrupted{false};
extern "C" void on_interrupt(int) { g_interrupted = true; }
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
  try {
    options = app::parse_command_line(argc, argv);
  } catch (const app::UsageError& e) {
    std::cerr << "povtrace: " << e.what() << "\nTry 'povtrace --help'.\n";
    return 2;
  }
  if (options.help) {
    std::cout << app::usage_text();
    return 0;
  }
  if (options.input.empty()) {
    std::cerr << "povtrace: no scene file given\nTry 'povtrace --help'.\n";
    return 2;
  }
  std::signal(SIGINT, on_interrupt);
  std::signal(SIGTERM, on_interrupt);
  try {
    if (options.vs_povray) return app::run_vs_povray(options, g_interrupted);
#ifdef POVTRACE_HAVE_MPI
    if (app::mpi_launched()) return app::run_mpi_render(options, g_interrupted);   // started by mpirun, N > 1
#endif
    return app::run_render(options, g_interrupted).exit_status;
  } catch (const app::UsageError& e) {   // found once the render starts, e.g. a region outside the image
    std::cerr << "povtrace: " << e.what() << "\nTry 'povtrace --help'.\n";
    return 2;
  } catch (const ParseError& e) {
    std::cerr << e.what() << "\n";
    return 1;
  } catch (const image::ImageError& e) {
    std::cerr << "povtrace: " << e.what() << "\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "povtrace: error: " << e.what() << "\n";
    return 1;
  }
}
