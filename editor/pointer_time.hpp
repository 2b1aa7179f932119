#pragma once
// The time of each pointer event on the renderer's clock (monotonic_s()), not the time the event
// loop handles it: while a frame is drawn, events wait and are handled together, so a steady
// pointer would reach the renderer in bursts sharing one time.
//
// Under X11 the X server's time of the MotionNotify / ButtonPress / ButtonRelease behind an SDL
// mouse event (read from the SDL_SYSWMEVENT that SDL queues just before it, matched by kind and
// position) is mapped to the local clock by EventClock. Elsewhere (Wayland, touch screens through
// XInput2, an event without its X event) the event keeps its handling time.
// GUI thread only.
#include <SDL.h>

#include <cstdint>

#include "editor/core/event_clock.hpp"

namespace vimg::editor {

class PointerTime {
 public:
  // Asks SDL for the window system's events (SDL_SYSWMEVENT) while on.
  void set_enabled(bool on);
  // Every event, in order of arrival; returns the time of a mouse event (its handling time when
  // the window system's time is not known).
  double time_of(const SDL_Event& event, double handled_s);

 private:
  struct ServerEvent {
    std::uint32_t sdl_type = 0;  // the SDL event it becomes: SDL_MOUSEMOTION, ...
    int x = 0;
    int y = 0;
    double time_s = 0.0;
  };
  bool enabled_ = false;
  bool pending_ = false;
  ServerEvent last_{};
  EventClock clock_;
};

}  // namespace vimg::editor
