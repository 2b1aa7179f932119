#include "cmdline/command_line.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <string_view>

namespace vimg::cmdline {
namespace {

bool parse_finite(std::string_view s, double& out) {
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  if (s.empty()) return false;
  const auto r = std::from_chars(s.data(), s.data() + s.size(), out);
  return r.ec == std::errc{} && r.ptr == s.data() + s.size() && std::isfinite(out);
}

std::string number_text(double v) {
  char buffer[32];
  const auto r = std::to_chars(buffer, buffer + sizeof buffer, v);
  return std::string(buffer, r.ptr);
}

int finish(CLI::App& app, const CLI::ParseError& e) {
  const std::string name = e.get_name();
  if (name == "CallForHelp" || name == "CallForAllHelp") {
    std::cout << app.help() << std::flush;  // the help of the subcommand asked about
    return kExitOk;
  }
  if (name == "CallForVersion") {
    std::cout << app.get_name() << ' ' << version() << std::endl;
    return kExitOk;
  }
  if (e.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success)) return kExitOk;
  // Name the subcommand the user was in: "vimg render: error: ...".
  std::string program = app.get_name();
  for (const CLI::App* at = &app; !at->get_subcommands().empty();) {
    at = at->get_subcommands().front();
    program += ' ' + at->get_name();
  }
  std::cerr << program << ": error: " << e.what() << "\nRun '" << program << " --help' for usage." << std::endl;
  return kExitUsage;
}

}  // namespace

const char* version() { return VIMG_VERSION; }

void configure(CLI::App& app, const std::string& program) {
  app.name(program);
  app.set_version_flag("--version", std::string(version()), "print the version and exit");
  app.set_help_flag("-h,--help", "print this help and exit");
  app.option_defaults()->always_capture_default();
}

std::optional<int> parse(CLI::App& app, int argc, const char* const* argv) {
  std::vector<std::string> args;
  for (int i = 1; i < argc; ++i) args.emplace_back(argv[i]);
  return parse(app, std::move(args));
}

std::optional<int> parse(CLI::App& app, std::vector<std::string> args) {
  std::reverse(args.begin(), args.end());  // CLI11 takes them last first
  try {
    app.parse(args);
  } catch (const CLI::ParseError& e) {
    return finish(app, e);
  }
  return std::nullopt;
}

CLI::Validator finite_in(double min, double max) {
  const std::string range = "in [" + number_text(min) + ", " + number_text(max) + "]";
  return CLI::Validator(
      [min, max, range](std::string& input) -> std::string {
        double v = 0.0;
        if (!parse_finite(input, v)) return "'" + input + "' is not a finite number";
        if (v < min || v > max) return "'" + input + "' is not " + range;
        return {};
      },
      "NUMBER " + range);
}

bool parse_point_2d(const std::string& text, double& x, double& y) {
  const auto comma = text.find(',');
  if (comma == std::string::npos) return false;
  return parse_finite(std::string_view(text).substr(0, comma), x) && parse_finite(std::string_view(text).substr(comma + 1), y);
}

CLI::Validator point_2d() {
  return CLI::Validator(
      [](std::string& input) -> std::string {
        double x = 0.0, y = 0.0;
        if (!parse_point_2d(input, x, y)) return "'" + input + "' is not X,Y with two finite numbers";
        return {};
      },
      "X,Y");
}

}  // namespace vimg::cmdline
