#include "apps/vimg-player/player_setup.hpp"

#include <cstdio>
#include <exception>

namespace vimg::player_app {

namespace {

double display_px_per_mm(int display, bool& from_dpi) {
  float dpi_diagonal = 0, dpi_horizontal = 0, dpi_vertical = 0;
  if (SDL_GetDisplayDPI(display, &dpi_diagonal, &dpi_horizontal, &dpi_vertical) == 0 && dpi_horizontal > 10.0f) {
    from_dpi = true;
    return static_cast<double>(dpi_horizontal) / 25.4;
  }
  from_dpi = false;
  return 96.0 / 25.4;  // the conventional desktop DPI when the display does not say
}

}  // namespace

ActuatorProfile load_profile_or_ideal(const PlayerArgs& args, bool& ok) {
  ok = true;
  ActuatorProfile profile;  // ideal, 175 Hz
  if (args.actuator_path) {
    const auto result = load_actuator_profile(*args.actuator_path);
    for (const auto& error : result.errors) std::fprintf(stderr, "%s\n", error.c_str());
    ok = result.profile.has_value();
    if (ok) profile = *result.profile;
  }
  return profile;
}

int PlayerActuator::open(const PlayerArgs& args) {
  bool profile_ok = false;
  profile_ = load_profile_or_ideal(args, profile_ok);
  if (!profile_ok) return 1;
  auto parsed = parse_output_spec(args.output);
  if (!parsed.spec) {
    std::fprintf(stderr, "vimg-player: %s\n", parsed.error.c_str());
    return 2;
  }
  spec_ = std::move(parsed.spec);
  signals_.emplace();
  try {
    output_ = open_output(*spec_, profile_);
  } catch (const std::exception& error) {
    std::fprintf(stderr, "vimg-player: %s\n", error.what());
    return 1;
  }
  rest_.emplace(output_->sink());
  return 0;
}

PlayerWindow::~PlayerWindow() {
  if (renderer != nullptr) SDL_DestroyRenderer(renderer);
  if (window != nullptr) SDL_DestroyWindow(window);
  if (video_started) SDL_QuitSubSystem(SDL_INIT_VIDEO);
}

std::optional<std::string> open_player_window(const PlayerArgs& args, const char* title, PlayerWindow& w) {
  if (SDL_InitSubSystem(SDL_INIT_VIDEO) != 0) return std::string("cannot start video: ") + SDL_GetError();
  w.video_started = true;
  const Uint32 flags = args.window_size ? SDL_WINDOW_SHOWN : (SDL_WINDOW_SHOWN | SDL_WINDOW_FULLSCREEN_DESKTOP);
  const auto [width, height] = args.window_size.value_or(std::pair{1024, 768});
  w.window = SDL_CreateWindow(title, SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED, width, height, flags);
  if (w.window == nullptr) {
    return std::string("cannot open a window (") + SDL_GetCurrentVideoDriver() + "): " + SDL_GetError();
  }
  w.renderer = SDL_CreateRenderer(w.window, -1, SDL_RENDERER_PRESENTVSYNC);
  if (w.renderer == nullptr) w.renderer = SDL_CreateRenderer(w.window, -1, SDL_RENDERER_SOFTWARE);
  if (w.renderer == nullptr) return std::string("cannot draw: ") + SDL_GetError();
  bool from_dpi = false;
  w.px_per_mm = args.px_per_mm.value_or(display_px_per_mm(SDL_GetWindowDisplayIndex(w.window), from_dpi));
  w.scale_source = args.px_per_mm ? "--px-per-mm" : (from_dpi ? "display dpi" : "96 dpi assumed");
  SDL_GetRendererOutputSize(w.renderer, &w.width_px, &w.height_px);
  return std::nullopt;
}

}  // namespace vimg::player_app
