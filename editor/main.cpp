// vimg-editor: the designer's application (drawing mode and playing mode).
#include "editor/editor_app.hpp"
#include "editor/editor_options.hpp"

int main(int argc, char** argv) {
  vimg::editor::ParsedOptions parsed = vimg::editor::parse_editor_options(argc, argv);
  if (!parsed.options) return parsed.exit_code;
  vimg::editor::EditorApp app(*parsed.options);
  return app.run();
}
