#include "storage/gesture_csv.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <map>
#include <system_error>

#include "storage/csv_lines.hpp"
#include "storage/decimal_chars.hpp"
#include "storage/diagnostic.hpp"
#include "storage/text_trim.hpp"
#include "storage/limits.hpp"
#include "storage/read_file.hpp"

namespace vimg {

namespace {

std::vector<std::string_view> split_fields(std::string_view line) {
  std::vector<std::string_view> fields;
  std::size_t start = 0;
  for (;;) {
    const std::size_t comma = line.find(',', start);
    if (comma == std::string_view::npos) {
      fields.push_back(trim_blanks(line.substr(start)));
      return fields;
    }
    fields.push_back(trim_blanks(line.substr(start, comma - start)));
    start = comma + 1;
  }
}

// A finite decimal number (locale independent; no hex, NaN or infinity).
bool parse_number(std::string_view s, double& out) {
  if (s.empty()) return false;
  for (char c : s) {
    if (!((c >= '0' && c <= '9') || c == '.' || c == '-' || c == '+' || c == 'e' || c == 'E')) return false;
  }
  if (s.front() == '+') s.remove_prefix(1);
  const auto r = decimal_from_chars(s.data(), s.data() + s.size(), out);
  return r.ec == std::errc{} && r.ptr == s.data() + s.size() && std::isfinite(out);
}

bool parse_finger(std::string_view s, int& out) {
  if (s.empty()) return false;
  const auto r = std::from_chars(s.data(), s.data() + s.size(), out);
  return r.ec == std::errc{} && r.ptr == s.data() + s.size();
}

// A field as it appears in a message: in quotes, escaped and cut (storage/diagnostic.hpp).
std::string quoted(std::string_view field) { return "'" + escape_input(field) + "'"; }

std::string format_number(double v) {
  char buf[64];
  const auto r = decimal_to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

}  // namespace

GestureParseResult parse_gesture_csv(std::string_view text, const std::string& file_name) {
  GestureParseResult result;
  auto error = [&](int line, const std::string& problem) {
    result.errors.push_back(file_name + ":" + std::to_string(line) + ": error: " + problem);
  };

  struct FingerState {
    bool down = false;
    double last_time_s = 0.0;
    bool has_time = false;
    std::size_t stroke = 0;  // index into strokes while down
  };
  std::map<int, FingerState> fingers;
  Gesture gesture;
  bool have_time = false;
  double min_time_s = 0.0, max_time_s = 0.0;  // over every row so far: the gesture's span
  CsvLines lines(text, {.trim_blanks = true, .max_rows = kMaxGestureRows});
  const std::optional<std::string_view> header = lines.header();
  if (header) {
    const auto f = split_fields(*header);
    const bool is_header = f.size() == 6 && f[0] == "time_s" && f[1] == "finger" && f[2] == "x_mm" &&
                           f[3] == "y_mm" && f[4] == "pressure" && f[5] == "phase";
    if (!is_header) {
      error(lines.line(), "expected the header row 'time_s,finger,x_mm,y_mm,pressure,phase'");
      return result;
    }
  }
  while (result.errors.size() < 50) {
    const std::optional<std::string_view> line = lines.row();
    if (!line) break;
    const int line_no = lines.line();
    const auto f = split_fields(*line);
    if (f.size() != 6) {
      error(line_no, "expected 6 fields (time_s,finger,x_mm,y_mm,pressure,phase), found " +
                         std::to_string(f.size()));
      continue;
    }
    GesturePoint p;
    int finger = 0;
    bool ok = true;
    // A finite number within +-limit; false (reported) otherwise.
    const auto bounded = [&](const char* name, std::string_view field, double limit, const char* unit, double& out) {
      if (!parse_number(field, out)) {
        error(line_no, std::string(name) + " " + quoted(field) + " is not a finite number");
        return false;
      }
      if (std::fabs(out) > limit) {
        error(line_no, std::string(name) + " " + quoted(field) + " is beyond " + format_number(limit) + " " + unit +
                           " (limit " + format_number(limit) + ")");
        return false;
      }
      return true;
    };
    if (!bounded("time_s", f[0], kMaxGestureTimeS, "s", p.time_s)) ok = false;
    if (!parse_finger(f[1], finger) || finger < 0 || finger > kMaxGestureFinger) {
      error(line_no, "finger " + quoted(f[1]) + " is not an integer in 0.." +
                         std::to_string(kMaxGestureFinger));
      ok = false;
    }
    if (!bounded("x_mm", f[2], kMaxGestureCoordinateMm, "mm", p.x_mm)) ok = false;
    if (!bounded("y_mm", f[3], kMaxGestureCoordinateMm, "mm", p.y_mm)) ok = false;
    if (f[4].empty()) {
      p.pressure = 1.0;
    } else if (!parse_number(f[4], p.pressure) || p.pressure < 0.0 || p.pressure > 1.0) {
      error(line_no, "pressure " + quoted(f[4]) + " is not a number in [0,1]");
      ok = false;
    }
    int phase = -1;
    if (f[5] == "down") phase = 0;
    else if (f[5] == "move") phase = 1;
    else if (f[5] == "up") phase = 2;
    else {
      error(line_no, "phase " + quoted(f[5]) + " is not down, move or up");
      ok = false;
    }
    if (!ok) continue;
    min_time_s = have_time ? std::min(min_time_s, p.time_s) : p.time_s;
    max_time_s = have_time ? std::max(max_time_s, p.time_s) : p.time_s;
    have_time = true;
    if (max_time_s - min_time_s > kMaxGestureDurationS) {
      error(line_no, "the gesture lasts more than " + format_number(kMaxGestureDurationS) + " s (limit " +
                         format_number(kMaxGestureDurationS) + ")");
      return result;
    }

    FingerState& st = fingers[finger];
    if (st.has_time && p.time_s < st.last_time_s) {
      error(line_no, "time " + format_number(p.time_s) + " s is before the previous row of finger " +
                         std::to_string(finger) + " (" + format_number(st.last_time_s) + " s)");
      continue;
    }
    st.has_time = true;
    st.last_time_s = p.time_s;
    if (phase == 0) {
      if (st.down) {
        error(line_no, "finger " + std::to_string(finger) + " is already down");
        continue;
      }
      st.down = true;
      st.stroke = gesture.strokes.size();
      gesture.strokes.push_back(GestureStroke{finger, {p}});
    } else {
      if (!st.down) {
        error(line_no, "finger " + std::to_string(finger) + " is not down (" + quoted(f[5]) +
                           " without a preceding down)");
        continue;
      }
      gesture.strokes[st.stroke].points.push_back(p);
      if (phase == 2) st.down = false;
    }
  }
  if (lines.past_row_limit()) {
    error(lines.line(), lines.row_limit_problem());
    return result;
  }
  if (!header && result.errors.empty()) {
    error(std::max(lines.line(), 1), "missing the header row 'time_s,finger,x_mm,y_mm,pressure,phase'");
  }
  if (!result.errors.empty()) return result;
  // Fingers still down at the end lift at their last row (nothing to add: the stroke ends there).
  std::stable_sort(gesture.strokes.begin(), gesture.strokes.end(), [](const auto& a, const auto& b) {
    return a.points.front().time_s < b.points.front().time_s;
  });
  result.gesture = std::move(gesture);
  return result;
}

GestureParseResult load_gesture_file(const std::filesystem::path& path) {
  FileReadResult read = read_regular_file(path, kMaxCsvFileBytes);
  if (!read.bytes) {
    GestureParseResult r;
    r.errors.push_back(path.string() + ": error: " + read.error);
    return r;
  }
  return parse_gesture_csv(*read.bytes, path.string());
}

std::string write_gesture_rows(const std::vector<GestureRow>& rows, std::string_view comment) {
  std::string out;
  if (!comment.empty()) out += "# " + std::string(comment) + "\n";
  out += "time_s,finger,x_mm,y_mm,pressure,phase\n";
  for (const GestureRow& r : rows) {
    out += format_number(r.time_s) + "," + std::to_string(r.finger) + "," + format_number(r.x_mm) + "," +
           format_number(r.y_mm) + "," + (r.pressure ? format_number(std::clamp(*r.pressure, 0.0, 1.0)) : std::string()) +
           "," + (r.phase == GesturePhase::down ? "down" : r.phase == GesturePhase::up ? "up" : "move") + "\n";
  }
  return out;
}

std::string write_gesture_csv(const Gesture& gesture) {
  std::vector<GestureRow> rows;
  for (const auto& s : gesture.strokes) {
    for (std::size_t i = 0; i < s.points.size(); ++i) {
      const GesturePhase phase = i == 0 ? GesturePhase::down : (i + 1 == s.points.size() ? GesturePhase::up : GesturePhase::move);
      const GesturePoint& p = s.points[i];
      rows.push_back({p.time_s, s.finger, p.x_mm, p.y_mm, p.pressure, phase});
    }
  }
  std::stable_sort(rows.begin(), rows.end(), [](const GestureRow& a, const GestureRow& b) { return a.time_s < b.time_s; });
  return write_gesture_rows(rows);
}

}  // namespace vimg
