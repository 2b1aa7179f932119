#include "apps/vimg-player/player_args.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>

namespace vimg::player_app {

namespace {
bool parse_double(const std::string& text, double& value) {
  const auto [end, status] = std::from_chars(text.data(), text.data() + text.size(), value);
  return !text.empty() && status == std::errc() && end == text.data() + text.size() && std::isfinite(value);
}
bool parse_int(const std::string& text, int& value) {
  const auto [end, status] = std::from_chars(text.data(), text.data() + text.size(), value);
  return !text.empty() && status == std::errc() && end == text.data() + text.size();
}
}  // namespace

ArgsResult parse_player_args(const std::vector<std::string>& arguments) {
  PlayerArgs args;
  for (std::size_t i = 0; i < arguments.size(); ++i) {
    const std::string& argument = arguments[i];
    auto value = [&](std::string& out) {
      if (i + 1 >= arguments.size()) return false;
      out = arguments[++i];
      return true;
    };
    std::string text;
    if (argument == "--help" || argument == "-h") {
      return {std::nullopt, ""};
    } else if (argument == "--calibrate") {
      args.calibrate = true;
    } else if (argument == "--output") {
      if (!value(args.output)) return {std::nullopt, "--output needs a value"};
    } else if (argument == "--actuator") {
      if (!value(text)) return {std::nullopt, "--actuator needs a file"};
      args.actuator_path = text;
    } else if (argument == "--px-per-mm") {
      double scale = 0.0;
      if (!value(text) || !parse_double(text, scale) || scale <= 0.0) {
        return {std::nullopt, "--px-per-mm needs a number above 0"};
      }
      args.px_per_mm = scale;
    } else if (argument == "--rate") {
      if (!value(text) || !parse_double(text, args.rate_hz) || args.rate_hz < 1.0 || args.rate_hz > 48000.0) {
        return {std::nullopt, "--rate needs a number of Hz in 1..48000"};
      }
    } else if (argument == "--realtime-priority") {
      int priority = -1;
      if (!value(text) || !parse_int(text, priority) || priority < 0 || priority > 99) {
        return {std::nullopt, "--realtime-priority needs a whole number in 0..99"};
      }
      args.realtime_priority = priority;
    } else if (argument == "--window") {
      int width = 0, height = 0;
      if (!value(text) || std::sscanf(text.c_str(), "%dx%d", &width, &height) != 2 || width < 64 || height < 64) {
        return {std::nullopt, "--window needs WIDTHxHEIGHT, e.g. 800x600"};
      }
      args.window_size = std::pair{width, height};
    } else if (!argument.empty() && argument[0] == '-') {
      return {std::nullopt, "unknown option " + argument};
    } else if (args.image_path.empty()) {
      args.image_path = argument;
    } else {
      return {std::nullopt, "only one IMAGE, not also " + argument};
    }
  }
  if (args.image_path.empty() && !args.calibrate) {
    return {std::nullopt, "needs an IMAGE"};
  }
  return {args, ""};
}

}  // namespace vimg::player_app
