#include "editor/core/gesture_recorder.hpp"

#include "storage/atomic_file.hpp"

#include <algorithm>
#include <system_error>

namespace vimg::editor {

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
  return write_gesture_rows(samples_, "recorded by vimg-editor in playing mode");
}

std::optional<std::string> GestureRecorder::save(const std::filesystem::path& path) const {
  return write_file_atomically(path, to_csv());
}

}  // namespace vimg::editor
