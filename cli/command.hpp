#pragma once
// One `vimg` subcommand per cli/cmd_*.cpp. Each adds itself to the `vimg` CLI11 app with its
// options and a callback that runs it and stores its exit status in `exit_code`.
#include "cmdline/command_line.hpp"

namespace vimg::cli {

using cmdline::kExitFailure;
using cmdline::kExitOk;
using cmdline::kExitUsage;

void add_validate_command(CLI::App& vimg, int& exit_code);
void add_convert_command(CLI::App& vimg, int& exit_code);
void add_info_command(CLI::App& vimg, int& exit_code);
void add_render_command(CLI::App& vimg, int& exit_code);
void add_gesture_command(CLI::App& vimg, int& exit_code);
// `vimg gesture predict` (cmd_gesture_predict.cpp), a subcommand of `vimg gesture`.
void add_gesture_predict(CLI::App& gesture, int& exit_code);
void add_volume_command(CLI::App& vimg, int& exit_code);
void add_import_command(CLI::App& vimg, int& exit_code);
void add_compare_command(CLI::App& vimg, int& exit_code);
void add_separate_command(CLI::App& vimg, int& exit_code);
void add_study_command(CLI::App& vimg, int& exit_code);
// `vimg study fit` (cmd_study_fit.cpp), a subcommand of `vimg study`.
void add_study_fit(CLI::App& study, int& exit_code);
void add_web_command(CLI::App& vimg, int& exit_code);
void add_serve_command(CLI::App& vimg, int& exit_code);

// A usage problem found after parsing (e.g. two options that do not go together): prints it in
// the cmdline format for `program` ("vimg render") and returns kExitUsage.
int usage_error(const char* program, const std::string& problem);

}  // namespace vimg::cli
