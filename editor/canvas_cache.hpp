#pragma once
// The canvas picture kept between frames. Tessellating and rasterizing 10 000 primitives every
// frame costs more than a frame (60 fps is 16.7 ms); the picture of the page and the document
// changes only with the document, the view or what is being played. So the canvas draws them once
// into an ImDrawList, renders that into an SDL texture, and each frame shows the texture with the
// selection, the handles, the previews and the finger on top. The key says when to draw again.
// Without render targets (or on a HiDPI framebuffer) the canvas draws directly, every frame.
// GUI thread only.
#include <SDL.h>
#include <imgui.h>

#include <cstdint>
#include <string>
#include <vector>

namespace vimg::editor {

// Everything the cached picture depends on.
struct CanvasCacheKey {
  std::uint64_t change = 0;            // the document's change_count (its value before a drag began)
  std::uint64_t feel = 0;              // the actuator choice's generation (its weak marks are drawn in)
  double px_per_mm = 0.0;
  float origin_x_px = 0.0f, origin_y_px = 0.0f;  // where page (0, 0) is
  int width_px = 0, height_px = 0;     // the canvas region
  bool grid = false;
  std::vector<std::string> left_out;   // elements drawn live instead (the selection being dragged)
  std::vector<std::size_t> highlighted;  // top-level elements under a finger
  friend bool operator==(const CanvasCacheKey&, const CanvasCacheKey&) = default;
};

class CanvasCache {
 public:
  explicit CanvasCache(SDL_Renderer* renderer);
  ~CanvasCache();
  CanvasCache(const CanvasCache&) = delete;
  CanvasCache& operator=(const CanvasCache&) = delete;

  // The renderer can draw into textures and the framebuffer is at 1 px per point.
  bool usable() const;
  // When `key` differs from the picture's: a cleared draw list to draw the picture into (screen
  // coordinates, clipped to the region), then end(). Null when the picture is current.
  ImDrawList* begin(const CanvasCacheKey& key, float x_px, float y_px);
  void end();
  // Shows the picture at the region's place.
  void show(ImDrawList* dl) const;
  std::uint64_t builds() const { return builds_; }
  // The texture's pixels were lost (SDL_RENDER_TARGETS_RESET): draw the picture again.
  void invalidate() { valid_ = false; }

 private:
  SDL_Renderer* renderer_;
  SDL_Texture* texture_ = nullptr;
  int texture_w_ = 0, texture_h_ = 0;
  ImDrawList list_;
  CanvasCacheKey key_;
  bool valid_ = false;
  float x_px_ = 0.0f, y_px_ = 0.0f;
  std::uint64_t builds_ = 0;
};

}  // namespace vimg::editor
