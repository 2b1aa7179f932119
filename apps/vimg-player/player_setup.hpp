#pragma once
// What playing an image and the matching test set up the same way: the actuator profile, and the
// window with its scale: full screen (or --window WxH), a vsync renderer (a software one when that
// fails), and the true scale from --px-per-mm, else the display's DPI, else 96 dpi.
// Threads: the UI thread.
#include <SDL.h>

#include <optional>
#include <string>

#include "apps/vimg-player/player_args.hpp"
#include "hal/actuator_profile.hpp"

namespace vimg::player_app {

// --actuator's profile, or the ideal actuator (175 Hz) without it. `ok` is false, with the errors
// on stderr, when the file cannot be read.
ActuatorProfile load_profile_or_ideal(const PlayerArgs& args, bool& ok);

struct PlayerWindow {
  SDL_Window* window = nullptr;
  SDL_Renderer* renderer = nullptr;
  bool video_started = false;
  int width_px = 0, height_px = 0;  // the renderer's output size
  double px_per_mm = 0.0;
  std::string scale_source;  // "--px-per-mm", "display dpi" or "96 dpi assumed"

  PlayerWindow() = default;
  ~PlayerWindow();
  PlayerWindow(const PlayerWindow&) = delete;
  PlayerWindow& operator=(const PlayerWindow&) = delete;
};

// Starts SDL video and opens the window titled `title`. Returns the error ("cannot open a window
// (x11): ...") when it cannot.
std::optional<std::string> open_player_window(const PlayerArgs& args, const char* title, PlayerWindow& window);

}  // namespace vimg::player_app
