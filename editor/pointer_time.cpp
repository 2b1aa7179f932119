#include "editor/pointer_time.hpp"

#include <SDL_syswm.h>

namespace vimg::editor {

void PointerTime::set_enabled(bool on) {
  enabled_ = on;
  pending_ = false;
  SDL_EventState(SDL_SYSWMEVENT, on ? SDL_ENABLE : SDL_DISABLE);
}

double PointerTime::time_of(const SDL_Event& event, double handled_s) {
  if (!enabled_) return handled_s;
#if defined(SDL_VIDEO_DRIVER_X11)
  if (event.type == SDL_SYSWMEVENT) {
    const SDL_SysWMmsg* msg = event.syswm.msg;
    if (msg == nullptr || msg->subsystem != SDL_SYSWM_X11) return handled_s;
    const XEvent& x = msg->msg.x11.event;
    if (x.type == MotionNotify) {
      last_ = {SDL_MOUSEMOTION, x.xmotion.x, x.xmotion.y, 0.0};
      last_.time_s = clock_.map(static_cast<std::uint32_t>(x.xmotion.time), handled_s);
      pending_ = true;
    } else if (x.type == ButtonPress || x.type == ButtonRelease) {
      last_ = {static_cast<std::uint32_t>(x.type == ButtonPress ? SDL_MOUSEBUTTONDOWN : SDL_MOUSEBUTTONUP),
               x.xbutton.x, x.xbutton.y, 0.0};
      last_.time_s = clock_.map(static_cast<std::uint32_t>(x.xbutton.time), handled_s);
      pending_ = true;
    }
    return handled_s;
  }
#endif
  int x = 0, y = 0;
  if (event.type == SDL_MOUSEMOTION) {
    x = event.motion.x;
    y = event.motion.y;
  } else if (event.type == SDL_MOUSEBUTTONDOWN || event.type == SDL_MOUSEBUTTONUP) {
    x = event.button.x;
    y = event.button.y;
  } else {
    return handled_s;
  }
  if (!pending_ || last_.sdl_type != event.type || last_.x != x || last_.y != y) return handled_s;
  pending_ = false;
  return last_.time_s;
}

}  // namespace vimg::editor
