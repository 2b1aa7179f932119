#pragma once
// `--print-layout`: where the window, the canvas and the widgets scripts click are, printed as
// "layout NAME X Y W H" lines (px, relative to the window) when a name first appears and whenever
// its place changes, never twice the same. Scripted tests read these lines instead of searching
// the screen. Disabled, it prints nothing.
#include <cstdio>
#include <string>
#include <vector>

namespace vimg::editor {

class LayoutLog {
 public:
  explicit LayoutLog(bool enabled, std::FILE* out = stdout) : enabled_(enabled), out_(out) {}
  bool enabled() const { return enabled_; }
  void print(const std::string& name, float x, float y, float w, float h);

 private:
  bool enabled_;
  std::FILE* out_;
  std::vector<std::string> printed_;  // the last line of each name
};

}  // namespace vimg::editor
