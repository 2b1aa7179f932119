#pragma once
// The status lines at the top of the screen: output, loop rate, jitter, underruns, scale, and the
// latest fault message.
#include <SDL.h>

#include <cstdint>
#include <string>

#include "player/realtime_renderer.hpp"

namespace vimg::player_app {

class StatusOverlay {
 public:
  StatusOverlay(std::string output, std::string scale_source, double px_per_mm)
      : output_(std::move(output)), scale_source_(std::move(scale_source)), px_per_mm_(px_per_mm) {}
  void note(const std::string& message) { last_message_ = message; }
  void draw(SDL_Renderer* renderer, const LoopStats& stats, std::uint64_t underruns) const;

 private:
  std::string output_;
  std::string scale_source_;
  double px_per_mm_;
  std::string last_message_;
};

}  // namespace vimg::player_app
