#include "storage/touch_trace/touch_log.hpp"

#include <array>
#include <cmath>

#include "storage/decimal_chars.hpp"
#include "storage/limits.hpp"

namespace vimg {

namespace {

constexpr std::size_t kFields = 6;

// Splits `line` at ';' into exactly kFields fields; false otherwise.
bool split_fields(std::string_view line, std::array<std::string_view, kFields>& fields) {
  std::size_t n = 0;
  std::size_t start = 0;
  for (std::size_t i = 0; i <= line.size(); ++i) {
    if (i == line.size() || line[i] == ';') {
      if (n == kFields) return false;
      fields[n++] = line.substr(start, i - start);
      start = i + 1;
    }
  }
  return n == kFields;
}

bool parse_finite(std::string_view text, double& value) {
  if (text.empty()) return false;
  const auto r = decimal_from_chars(text.data(), text.data() + text.size(), value);
  return r.ec == std::errc() && r.ptr == text.data() + text.size() && std::isfinite(value);
}

std::string_view trimmed_line(std::string_view line) {
  while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.remove_suffix(1);
  return line;
}

}  // namespace

bool looks_like_touch_log(std::string_view text) {
  std::size_t pos = 0;
  while (pos < text.size()) {
    const std::size_t end = std::min(text.find('\n', pos), text.size());
    const std::string_view line = trimmed_line(text.substr(pos, end - pos));
    pos = end + 1;
    if (line.empty()) continue;
    std::array<std::string_view, kFields> f;
    double v = 0.0;
    if (!split_fields(line, f)) return false;
    for (std::string_view field : f) {
      if (!parse_finite(field, v)) return false;
    }
    return true;
  }
  return false;
}

TouchTraceParseResult parse_touch_log(std::string_view text, const std::string& file_name) {
  DiagnosticList diagnostics(file_name);
  TouchTrace trace;
  trace.protocol = TouchTrace::Protocol::single;
  bool in_contact = false;
  bool have_first = false;
  double first_ms = 0.0, last_ms = 0.0;
  std::size_t events = 0;
  int line_number = 0;
  std::size_t pos = 0;
  while (pos < text.size() && !diagnostics.has_errors()) {
    const std::size_t end = std::min(text.find('\n', pos), text.size());
    const std::string_view line = trimmed_line(text.substr(pos, end - pos));
    pos = end + 1;
    ++line_number;
    if (line.empty()) continue;
    std::array<std::string_view, kFields> f;
    if (!split_fields(line, f)) {
      diagnostics.error(line_number, "expected 6 fields separated by ';' (epoch_ms;time_ms;x;y;size;action), got '" +
                                         escape_input(line) + "'");
      break;
    }
    std::array<double, kFields> v{};
    static constexpr std::array<const char*, kFields> kNames = {"epoch_ms", "time_ms", "x", "y", "size", "action"};
    bool numbers = true;
    for (std::size_t i = 0; i < kFields && numbers; ++i) {
      if (!parse_finite(f[i], v[i])) {
        diagnostics.error(line_number, std::string(kNames[i]) + " is not a finite number: '" + escape_input(f[i]) + "'");
        numbers = false;
      }
    }
    if (!numbers) break;
    const double action = v[5];
    if (action != 0.0 && action != 1.0 && action != 2.0) {
      diagnostics.error(line_number, "action must be 0 (down), 1 (up) or 2 (move), got '" + escape_input(f[5]) + "'");
      break;
    }
    if (have_first && v[1] < last_ms) {
      diagnostics.error(line_number, "time_ms goes back from " + std::string(f[1]) + " to below the previous line's");
      break;
    }
    if (!have_first) first_ms = v[1];
    if ((v[1] - first_ms) / 1000.0 > kMaxGestureDurationS) {
      diagnostics.error(line_number, touch_trace_too_long_problem());
      break;
    }
    have_first = true;
    last_ms = v[1];
    if (++events > kMaxGestureRows) {
      diagnostics.error(line_number, "more than " + std::to_string(kMaxGestureRows) + " events (docs/limits.md)");
      break;
    }
    TouchSample sample;
    sample.time_s = (v[1] - first_ms) / 1000.0;
    sample.x = v[2];
    sample.y = v[3];
    sample.pressure = v[4];
    sample.line = line_number;
    if (action == 0.0) {
      if (in_contact) {
        diagnostics.error(line_number, "a down before the previous touch's up");
        break;
      }
      sample.phase = TouchSample::Phase::down;
      trace.contacts.push_back(TouchContact{0, {sample}});
      in_contact = true;
      continue;
    }
    if (!in_contact) {
      diagnostics.error(line_number, action == 1.0 ? "an up without a down" : "a move without a down");
      break;
    }
    sample.phase = action == 1.0 ? TouchSample::Phase::up : TouchSample::Phase::move;
    trace.contacts.back().samples.push_back(sample);
    if (action == 1.0) in_contact = false;
  }
  if (!diagnostics.has_errors() && !have_first) diagnostics.error(0, "no touch events");
  if (!diagnostics.has_errors() && in_contact) {
    // A log cut before the last up: that touch ends at its last event.
    // A lone down gets its up as one more sample, which must still fit in a gesture's rows.
    TouchContact& last = trace.contacts.back();
    if (last.samples.size() < 2 && events >= kMaxGestureRows) {
      diagnostics.error(line_number, "the log ends during a touch, and its up would be gesture row " +
                                         std::to_string(events + 1) + " (limit " + std::to_string(kMaxGestureRows) +
                                         " gesture rows)");
    } else {
      if (last.samples.size() < 2) last.samples.push_back(last.samples.back());
      last.samples.back().phase = TouchSample::Phase::up;
      diagnostics.warning(line_number, "the log ends during a touch: it is lifted at its last event");
    }
  }
  trace.duration_s = (last_ms - first_ms) / 1000.0;
  trace.last_line = line_number;
  TouchTraceParseResult r;
  if (!diagnostics.has_errors()) r.trace = std::move(trace);
  r.diagnostics = diagnostics.take();
  return r;
}

}  // namespace vimg
