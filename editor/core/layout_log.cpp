#include "editor/core/layout_log.hpp"

namespace vimg::editor {

void LayoutLog::print(const std::string& name, float x, float y, float w, float h) {
  if (!enabled_) return;
  char numbers[160];
  std::snprintf(numbers, sizeof numbers, " %.0f %.0f %.0f %.0f", static_cast<double>(x), static_cast<double>(y),
                static_cast<double>(w), static_cast<double>(h));
  const std::string prefix = "layout " + name + " ";
  const std::string line = "layout " + name + numbers;
  bool known = false;
  for (std::string& s : printed_) {
    if (s.rfind(prefix, 0) != 0) continue;
    if (s == line) return;
    s = line;
    known = true;
    break;
  }
  if (!known) printed_.push_back(line);
  std::fprintf(out_, "%s\n", line.c_str());
  std::fflush(out_);
}

}  // namespace vimg::editor
