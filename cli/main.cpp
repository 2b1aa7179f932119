// `vimg`: the headless command (spec section 4). Each subcommand lives in its own cli/cmd_*.cpp.
#include <cstdio>

#include "cli/command.hpp"
#include "storage/atomic_file.hpp"

namespace vimg::cli {

int usage_error(const char* program, const std::string& problem) {
  std::fprintf(stderr, "%s: error: %s\nRun '%s --help' for usage.\n", program, problem.c_str(), program);
  return kExitUsage;
}

}  // namespace vimg::cli

int main(int argc, char** argv) {
  using namespace vimg::cli;
  // SIGINT/SIGTERM: no half-written file is left (every output goes through AtomicFileWriter) and
  // vimg exits 130/143. `vimg render` installs its own handlers while it renders.
  vimg::exit_on_interrupt_removing_temporaries();
  CLI::App app("vimg: validate, convert, inspect and render vibrotactile images, headless.");
  vimg::cmdline::configure(app, "vimg");
  int exit_code = kExitOk;
  add_validate_command(app, exit_code);
  add_convert_command(app, exit_code);
  add_info_command(app, exit_code);
  add_render_command(app, exit_code);
  add_gesture_command(app, exit_code);
  add_volume_command(app, exit_code);
  add_import_command(app, exit_code);
  add_compare_command(app, exit_code);
  add_separate_command(app, exit_code);
  add_study_command(app, exit_code);
  add_web_command(app, exit_code);
  add_serve_command(app, exit_code);
  app.require_subcommand(1);
  if (auto code = vimg::cmdline::parse(app, argc, argv)) return *code;
  return exit_code;
}
