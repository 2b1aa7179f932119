#include "editor/canvas_cache.hpp"

#include <imgui_impl_sdlrenderer.h>

namespace vimg::editor {

CanvasCache::CanvasCache(SDL_Renderer* renderer) : renderer_(renderer), list_(ImGui::GetDrawListSharedData()) {}

CanvasCache::~CanvasCache() {
  if (texture_) SDL_DestroyTexture(texture_);
}

bool CanvasCache::usable() const {
  const ImVec2 scale = ImGui::GetIO().DisplayFramebufferScale;
  return renderer_ && SDL_RenderTargetSupported(renderer_) && scale.x == 1.0f && scale.y == 1.0f;
}

ImDrawList* CanvasCache::begin(const CanvasCacheKey& key, float x_px, float y_px) {
  if (valid_ && key == key_ && x_px == x_px_ && y_px == y_px_) return nullptr;
  if (!texture_ || texture_w_ != key.width_px || texture_h_ != key.height_px) {
    if (texture_) SDL_DestroyTexture(texture_);
    texture_ = SDL_CreateTexture(renderer_, SDL_PIXELFORMAT_ARGB8888, SDL_TEXTUREACCESS_TARGET, key.width_px,
                                 key.height_px);
    if (!texture_) {
      valid_ = false;
      return nullptr;
    }
    SDL_SetTextureBlendMode(texture_, SDL_BLENDMODE_BLEND);
    SDL_SetTextureScaleMode(texture_, SDL_ScaleModeNearest);  // shown 1:1
    texture_w_ = key.width_px;
    texture_h_ = key.height_px;
  }
  key_ = key;
  x_px_ = x_px;
  y_px_ = y_px;
  list_._ResetForNewFrame();
  list_.PushTextureID(ImGui::GetIO().Fonts->TexID);
  list_.PushClipRect(ImVec2(x_px, y_px), ImVec2(x_px + static_cast<float>(key.width_px), y_px + static_cast<float>(key.height_px)));
  return &list_;
}

void CanvasCache::end() {
  // The backend passes vertex positions through as they are: move them into the texture.
  for (ImDrawVert& v : list_.VtxBuffer) {
    v.pos.x -= x_px_;
    v.pos.y -= y_px_;
  }
  ImDrawList* lists[1] = {&list_};
  ImDrawData data;
  data.Valid = true;
  data.CmdLists = lists;
  data.CmdListsCount = 1;
  data.TotalVtxCount = list_.VtxBuffer.Size;
  data.TotalIdxCount = list_.IdxBuffer.Size;
  data.DisplayPos = ImVec2(x_px_, y_px_);  // clip rectangles stay in screen coordinates
  data.DisplaySize = ImVec2(static_cast<float>(texture_w_), static_cast<float>(texture_h_));
  data.FramebufferScale = ImVec2(1.0f, 1.0f);
  SDL_Texture* previous = SDL_GetRenderTarget(renderer_);
  SDL_SetRenderTarget(renderer_, texture_);
  SDL_SetRenderDrawColor(renderer_, 0, 0, 0, 0);
  SDL_RenderClear(renderer_);
  ImGui_ImplSDLRenderer_RenderDrawData(&data);
  SDL_SetRenderTarget(renderer_, previous);
  valid_ = true;
  ++builds_;
}

void CanvasCache::show(ImDrawList* dl) const {
  if (!valid_ || !texture_) return;
  dl->AddImage(static_cast<ImTextureID>(texture_), ImVec2(x_px_, y_px_),
               ImVec2(x_px_ + static_cast<float>(texture_w_), y_px_ + static_cast<float>(texture_h_)));
}

}  // namespace vimg::editor
