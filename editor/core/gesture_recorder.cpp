#include "editor/core/gesture_recorder.hpp"

#include "storage/atomic_file.hpp"

#include <algorithm>
#include <charconv>
#include <fstream>
#include <system_error>

namespace vimg::editor {
namespace {

std::string number(double v) {
  char buf[64];
  auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed, 6);
  if (ec != std::errc()) return "0";
  std::string s(buf, end);
  // Trim trailing zeros but keep at least three decimals, as in the spec's example.
  while (s.size() > 1 && s.back() == '0' && s.find('.') != std::string::npos &&
         s.size() - s.find('.') > 4) {
    s.pop_back();
  }
  return s;
}

const char* phase_name(GesturePhase p) {
  switch (p) {
    case GesturePhase::down: return "down";
    case GesturePhase::move: return "move";
    case GesturePhase::up: return "up";
  }
  return "move";
}

}  // namespace

void GestureRecorder::add(GestureSample sample) {
  for (auto it = samples_.rbegin(); it != samples_.rend(); ++it) {
    if (it->finger == sample.finger) {
      sample.time_s = std::max(sample.time_s, it->time_s);
      break;
    }
  }
  samples_.push_back(sample);
}

std::string GestureRecorder::to_csv() const {
  std::string out = "# recorded by vimg-editor in playing mode\ntime_s,finger,x_mm,y_mm,pressure,phase\n";
  for (const GestureSample& s : samples_) {
    out += number(s.time_s) + "," + std::to_string(s.finger) + "," + number(s.x_mm) + "," + number(s.y_mm) + ",";
    if (s.pressure) out += number(std::clamp(*s.pressure, 0.0, 1.0));
    out += ",";
    out += phase_name(s.phase);
    out += "\n";
  }
  return out;
}

std::optional<std::string> GestureRecorder::save(const std::filesystem::path& path) const {
  return write_file_atomically(path, to_csv());
}

}  // namespace vimg::editor
