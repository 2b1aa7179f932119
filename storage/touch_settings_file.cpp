#include "storage/touch_settings_file.hpp"

#include <cmath>
#include <system_error>
#include <variant>

#include "primitives/touch_prediction/touch_latency_defaults.hpp"
#include "storage/atomic_file.hpp"
#include "storage/number_text.hpp"
#include "storage/load_file.hpp"
#include "storage/text_trim.hpp"

namespace vimg {

namespace {

void parse_line(std::string_view line, int line_number, TouchSettings& s, DiagnosticList& problems) {
  const std::size_t equals = line.find('=');
  if (equals == std::string_view::npos) {
    problems.error(line_number, "expected `key = value`, found '" + escape_input(line) + "'");
    return;
  }
  const std::string_view key = trim_blanks(line.substr(0, equals));
  const std::string_view value = trim_blanks(line.substr(equals + 1));
  if (key == "touch_latency_ms") {
    if (s.latency_ms) {
      problems.error(line_number, "touch_latency_ms is given twice");
      return;
    }
    const ParsedNumber n = parse_decimal(value);
    const double max_ms = kMaxTouchPanelLatency_s * 1e3;
    if (const double* ms = std::get_if<double>(&n); ms && std::isfinite(*ms) && *ms >= 0.0 && *ms <= max_ms) {
      s.latency_ms = *ms;
    } else {
      problems.error(line_number, "touch_latency_ms must be a number of ms from 0 to " + format_decimal(max_ms) +
                                      ", found '" + escape_input(value) + "'");
    }
  } else if (key == "touch_prediction") {
    if (s.prediction) {
      problems.error(line_number, "touch_prediction is given twice");
    } else if (value == "on" || value == "off") {
      s.prediction = value == "on";
    } else {
      problems.error(line_number, "touch_prediction must be on or off, found '" + escape_input(value) + "'");
    }
  } else {
    problems.error(line_number, "unknown setting '" + escape_input(key) +
                                    "' (the settings are touch_latency_ms and touch_prediction)");
  }
}

}  // namespace

TouchSettingsRead parse_touch_settings(std::string_view text, const std::string& file) {
  TouchSettingsRead out;
  DiagnosticList problems(file);
  int line_number = 0;
  while (!text.empty()) {
    ++line_number;
    const std::size_t end = text.find('\n');
    std::string_view line = text.substr(0, end);
    text = end == std::string_view::npos ? std::string_view() : text.substr(end + 1);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    line = trim_blanks(line);
    if (line.empty() || line.front() == '#') continue;
    parse_line(line, line_number, out.settings, problems);
  }
  out.diagnostics = problems.take();
  return out;
}

TouchSettingsRead read_touch_settings(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) return {};
  return load_file<TouchSettingsRead>(path, kMaxTouchSettingsBytes, parse_touch_settings);
}

std::string touch_settings_text(double latency_ms, bool prediction, std::string_view program) {
  std::string out = "# " + std::string(program) + ": touch-latency compensation on this device (docs/latency.md)\n";
  out += "touch_latency_ms = " + format_decimal(latency_ms) + "\n";
  out += std::string("touch_prediction = ") + (prediction ? "on" : "off") + "\n";
  return out;
}

std::optional<std::string> write_touch_settings(const std::filesystem::path& path, double latency_ms,
                                                bool prediction, std::string_view program) {
  std::error_code ec;
  std::filesystem::create_directories(path.parent_path(), ec);
  return write_file_atomically(path, touch_settings_text(latency_ms, prediction, program));
}

}  // namespace vimg
