#include "apps/vimg-player/touch_input.hpp"

namespace vimg::player_app {

TouchEvent TouchInput::make(int finger, TouchPhase phase, double x_px, double y_px, double pressure) {
  where_px_[static_cast<std::size_t>(finger)] = {static_cast<float>(x_px), static_cast<float>(y_px)};
  TouchEvent touch;
  touch.time_s = monotonic_s();
  touch.finger = finger;
  touch.phase = phase;
  touch.x_mm = view_.to_x_mm(x_px);
  touch.y_mm = view_.to_y_mm(y_px);
  touch.pressure = pressure;
  return touch;
}

int TouchInput::slot_for(SDL_FingerID id, bool allocate) {
  for (int slot = 1; slot < kSlots; ++slot) {
    if (in_use_[static_cast<std::size_t>(slot)] && finger_ids_[static_cast<std::size_t>(slot)] == id) return slot;
  }
  if (!allocate) return -1;
  for (int slot = 1; slot < kSlots; ++slot) {
    if (!in_use_[static_cast<std::size_t>(slot)]) {
      in_use_[static_cast<std::size_t>(slot)] = true;
      finger_ids_[static_cast<std::size_t>(slot)] = id;
      return slot;
    }
  }
  return -1;  // more fingers than slots: ignored
}

std::vector<TouchEvent> TouchInput::translate(const SDL_Event& event) {
  std::vector<TouchEvent> events;
  switch (event.type) {
    case SDL_MOUSEBUTTONDOWN:
      if (event.button.which != SDL_TOUCH_MOUSEID && event.button.button == SDL_BUTTON_LEFT) {
        mouse_down_ = true;
        in_use_[0] = true;
        events.push_back(make(0, TouchPhase::down, event.button.x, event.button.y, 1.0));
      }
      break;
    case SDL_MOUSEMOTION:
      if (event.motion.which != SDL_TOUCH_MOUSEID && mouse_down_) {
        events.push_back(make(0, TouchPhase::move, event.motion.x, event.motion.y, 1.0));
      }
      break;
    case SDL_MOUSEBUTTONUP:
      if (event.button.which != SDL_TOUCH_MOUSEID && event.button.button == SDL_BUTTON_LEFT && mouse_down_) {
        mouse_down_ = false;
        in_use_[0] = false;
        events.push_back(make(0, TouchPhase::up, event.button.x, event.button.y, 1.0));
      }
      break;
    case SDL_FINGERDOWN:
    case SDL_FINGERMOTION:
    case SDL_FINGERUP: {
      const bool down = event.type == SDL_FINGERDOWN;
      const int slot = slot_for(event.tfinger.fingerId, down);
      if (slot < 0) break;
      const TouchPhase phase = down ? TouchPhase::down : (event.type == SDL_FINGERUP ? TouchPhase::up : TouchPhase::move);
      events.push_back(make(slot, phase, static_cast<double>(event.tfinger.x) * width_,
                            static_cast<double>(event.tfinger.y) * height_, static_cast<double>(event.tfinger.pressure)));
      if (phase == TouchPhase::up) in_use_[static_cast<std::size_t>(slot)] = false;
      break;
    }
    default:
      break;
  }
  return events;
}

void TouchInput::draw_fingers(SDL_Renderer* renderer) const {
  SDL_SetRenderDrawColor(renderer, 220, 60, 40, 255);
  for (int slot = 0; slot < kSlots; ++slot) {
    if (!in_use_[static_cast<std::size_t>(slot)]) continue;
    const SDL_FPoint p = where_px_[static_cast<std::size_t>(slot)];
    const SDL_FRect mark{p.x - 6.0f, p.y - 6.0f, 12.0f, 12.0f};
    SDL_RenderDrawRectF(renderer, &mark);
  }
}

}  // namespace vimg::player_app
