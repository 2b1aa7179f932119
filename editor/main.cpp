// vimg-editor: the designer's application (drawing mode and playing mode).
#include <cstdio>

#include "editor/editor_app.hpp"
#include "editor/editor_options.hpp"

int main(int argc, char** argv) {
  vimg::editor::ParsedOptions parsed = vimg::editor::parse_editor_options(argc, argv);
  if (!parsed.options) {
    std::fputs(parsed.message.c_str(), parsed.exit_code == 0 ? stdout : stderr);
    return parsed.exit_code;
  }
  vimg::editor::EditorApp app(*parsed.options);
  return app.run();
}
