#pragma once
// Records the finger's path in playing mode and writes it as a gesture file (spec section 3,
// storage/gesture_csv.hpp), which `vimg render` can replay.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "storage/gesture_csv.hpp"

namespace vimg::editor {

using GestureSample = GestureRow;  // one row of the file

class GestureRecorder {
 public:
  void clear() { samples_.clear(); }
  // Appends a sample; times before the finger's last one are raised to it (time never decreases).
  void add(GestureSample sample);
  const std::vector<GestureSample>& samples() const { return samples_; }
  bool empty() const { return samples_.empty(); }

  std::string to_csv() const;
  // Writes atomically. Returns an error message, or nothing on success.
  std::optional<std::string> save(const std::filesystem::path& path) const;

 private:
  std::vector<GestureSample> samples_;
};

}  // namespace vimg::editor
