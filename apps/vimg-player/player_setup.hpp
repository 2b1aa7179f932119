#pragma once
// What playing an image and the matching test set up the same way: the actuator profile and the
// output it drives, put to rest however the run ends, and the window with its scale: full screen (or --window WxH), a vsync renderer (a software one when that
// fails), and the true scale from --px-per-mm, else the display's DPI, else 96 dpi.
// Threads: the UI thread.
#include <SDL.h>

#include <memory>
#include <optional>
#include <string>

#include "apps/vimg-player/player_args.hpp"
#include "storage/actuator_profile.hpp"
#include "hal/output_spec.hpp"
#include "hal/rest_on_exit.hpp"

namespace vimg::player_app {

// --actuator's profile, or the ideal actuator (175 Hz) without it. `ok` is false, with the errors
// on stderr, when the file cannot be read.
ActuatorProfile load_profile_or_ideal(const PlayerArgs& args, bool& ok);

// The actuator a run drives: the profile (load_profile_or_ideal), the output --output names opened
// with it, SIGINT/SIGTERM putting it to rest from the moment it is opened (SignalRestScope), and a
// RestGuard: whatever happens after open(), the actuator ends at rest when this goes.
class PlayerActuator {
 public:
  PlayerActuator() = default;
  PlayerActuator(const PlayerActuator&) = delete;
  PlayerActuator& operator=(const PlayerActuator&) = delete;

  // 0 when the output is open; else the exit status, with the problem on stderr: 1 for a profile that
  // cannot be read or an output that cannot be opened, 2 for a bad --output. Called once.
  int open(const PlayerArgs& args);

  const ActuatorProfile& profile() const { return profile_; }
  const OutputSpec& spec() const { return *spec_; }
  Output& output() const { return *output_; }

 private:
  ActuatorProfile profile_;
  std::optional<OutputSpec> spec_;
  std::optional<SignalRestScope> signals_;
  std::unique_ptr<Output> output_;
  std::optional<RestGuard> rest_;  // last: the actuator is at rest before the output closes
};

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
