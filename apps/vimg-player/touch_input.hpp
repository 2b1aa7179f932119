#pragma once
// SDL input to the renderer's touch events: the mouse (left button) is finger 0, touchscreen
// fingers take the remaining slots. Positions become millimetres on the image.
#include <SDL.h>

#include <array>
#include <cstdint>
#include <vector>

#include "apps/vimg-player/image_view.hpp"
#include "player/touch_event.hpp"

namespace vimg::player_app {

class TouchInput {
 public:
  TouchInput(const ViewTransform& view, int window_width_px, int window_height_px)
      : view_(view), width_(window_width_px), height_(window_height_px) {}

  std::vector<TouchEvent> translate(const SDL_Event& event);
  void draw_fingers(SDL_Renderer* renderer) const;

 private:
  static constexpr int kSlots = 10;
  int slot_for(SDL_FingerID id, bool allocate);
  TouchEvent make(int finger, TouchPhase phase, double x_px, double y_px, double pressure);

  ViewTransform view_;
  int width_;
  int height_;
  bool mouse_down_ = false;
  std::array<SDL_FingerID, kSlots> finger_ids_{};
  std::array<bool, kSlots> in_use_{};
  std::array<SDL_FPoint, kSlots> where_px_{};
};

}  // namespace vimg::player_app
