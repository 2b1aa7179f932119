#include "editor/worker_window.hpp"

#include <SDL.h>

#include <algorithm>

#include "editor/core/layout_log.hpp"

namespace vimg::editor {

void wake_gui() {
  SDL_Event e{};
  e.type = SDL_USEREVENT;
  SDL_PushEvent(&e);
}

ImU32 confusion_shade(double p) {
  const float s = static_cast<float>(std::clamp(p, 0.0, 1.0));
  return ImGui::GetColorU32(ImVec4(0.12f + s * (0.16f - 0.12f), 0.13f + s * (0.38f - 0.13f), 0.16f + s * (0.75f - 0.16f), 1.0f));
}

void print_last_item(LayoutLog& layout, const std::string& name) {
  layout.print(name, ImGui::GetItemRectMin().x, ImGui::GetItemRectMin().y, ImGui::GetItemRectSize().x,
               ImGui::GetItemRectSize().y);
}

}  // namespace vimg::editor
