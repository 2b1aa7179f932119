// vimg-player: plays a vibrotactile image under the finger (or mouse) through a chosen output, or
// runs the matching test of a study file (--study, study_session.hpp).
#include <SDL.h>

#include <cstdio>
#include <exception>
#include <memory>
#include <string>
#include <vector>

#include "apps/vimg-player/image_view.hpp"
#include "apps/vimg-player/player_args.hpp"
#include "apps/vimg-player/player_setup.hpp"
#include "apps/vimg-player/status_overlay.hpp"
#include "apps/vimg-player/status_text.hpp"
#include "apps/vimg-player/study_session.hpp"
#include "apps/vimg-player/touch_input.hpp"
#include "storage/actuator_profile.hpp"
#include "hal/output_spec.hpp"
#include "hal/rest_on_exit.hpp"
#include "player/actuator_sink.hpp"
#include "player/realtime_renderer.hpp"
#include "player/scene.hpp"
#include "realtime/realtime_priority.hpp"
#include "storage/image_io.hpp"
#include "storage/print_diagnostics.hpp"

namespace vimg::player_app {

namespace {

int calibrate(const ActuatorProfile& profile, const OutputSpec& spec) {
  SignalRestScope signals;
  try {
    auto output = open_output(spec, profile);
    RestGuard rest(output->sink());
    std::printf("%s\n", output->calibrate().c_str());
    return 0;
  } catch (const std::exception& error) {
    std::fprintf(stderr, "vimg-player: %s\n", error.what());
    return 1;
  }
}

int run(const PlayerArgs& args) {
  if (args.study_path) return run_study(args);
  if (args.calibrate) {
    bool ok = false;
    const ActuatorProfile profile = load_profile_or_ideal(args, ok);
    const auto spec = parse_output_spec(args.output);
    if (!ok) return 1;
    if (!spec.spec) {
      std::fprintf(stderr, "vimg-player: %s\n", spec.error.c_str());
      return 2;
    }
    return calibrate(profile, *spec.spec);
  }
  const LoadResult loaded = load_image_file(args.image_path);
  print_diagnostics(loaded.diagnostics);
  if (!loaded.ok()) return 1;
  const Image& image = *loaded.image;

  PlayerActuator actuator;  // whatever happens below, the actuator ends at rest
  if (const int status = actuator.open(args)) return status;
  const ActuatorProfile& profile = actuator.profile();
  Output& output = actuator.output();

  SceneOptions scene_options;
  scene_options.carrier_frequency_hz = profile.resonance_hz;
  auto scene = compile_scene(image, scene_options);

  PlayerWindow sdl;
  if (auto error = open_player_window(args, "vimg-player", sdl)) {
    std::fprintf(stderr, "vimg-player: %s\n", error->c_str());
    return 1;
  }
  const double px_per_mm = sdl.px_per_mm;
  const int window_width = sdl.width_px, window_height = sdl.height_px;
  ViewTransform view;
  view.px_per_mm = px_per_mm;
  view.origin_x_px = (window_width - image.width_mm * px_per_mm) / 2.0;
  view.origin_y_px = (window_height - image.height_mm * px_per_mm) / 2.0;

  RealtimeOptions realtime;
  realtime.sample_rate_hz = args.rate_hz;
  realtime.realtime_priority = args.realtime_priority;
  realtime.touch = args.touch;
  // Threads: this one (UI, control), the render thread (renderer) and, for a hardware output, the
  // device service thread, which the output's sink runs between open() and close() (started by
  // renderer.start(), stopped by renderer.stop()): it formats the driver's fault codes into the
  // messages taken below and reconnects a lost device, off the render thread.
  // --equalize: the drive goes through the actuator's equalizer on its way to the output (designed
  // in open(), before the render thread starts; real-time safe, player/actuator_sink.hpp).
  ActuatorSink equalizing(output.sink(), profile.response, OutputSignal::drive, true);
  DriveSink& drive_path = args.equalize ? static_cast<DriveSink&>(equalizing) : output.sink();
  RealtimeRenderer renderer(drive_path, realtime);
  renderer.set_scene(scene);
  if (auto error = renderer.start()) {
    std::fprintf(stderr, "vimg-player: %s\n", error->c_str());
    return 1;
  }

  StatusText status(output.description(), sdl.scale_source, px_per_mm);
  auto report_messages = [&] {
    for (auto& message : output.take_messages()) {
      std::fprintf(stderr, "vimg-player: %s\n", message.c_str());
      status.note(std::move(message));
    }
  };
  TouchInput input(view, window_width, window_height);
  bool quit = false;
  while (!quit && !rest_requested()) {
    SDL_Event event;
    while (SDL_PollEvent(&event)) {
      if (event.type == SDL_QUIT) quit = true;
      if (event.type == SDL_KEYDOWN && (event.key.keysym.sym == SDLK_ESCAPE || event.key.keysym.sym == SDLK_q)) {
        quit = true;
      }
      for (const TouchEvent& touch : input.translate(event)) {
        if (!renderer.push_event(touch)) status.note("input queue full: event dropped");
      }
    }
    report_messages();
    SDL_SetRenderDrawColor(sdl.renderer, 30, 30, 34, 255);
    SDL_RenderClear(sdl.renderer);
    draw_image(sdl.renderer, image, view);
    input.draw_fingers(sdl.renderer);
    draw_status_panel(sdl.renderer, status.lines(renderer.stats(), output.underruns(), output.device_gone()));
    SDL_RenderPresent(sdl.renderer);
    SDL_Delay(10);
  }
  renderer.stop();  // stops the thread (and the device service) and puts the output to rest
  report_messages();  // the last faults of the session, drained when the service stopped
  const LoopStats stats = renderer.stats();
  std::printf("vimg-player: %s; %llu blocks at %.0f Hz, jitter p99 %.3f ms, max %.3f ms, %llu underruns; %s%s\n",
              output.description().c_str(), static_cast<unsigned long long>(stats.blocks), stats.measured_rate_hz,
              stats.jitter_p99_s * 1e3, stats.jitter_max_s * 1e3,
              static_cast<unsigned long long>(output.underruns()), describe(stats.priority).c_str(),
              rest_requested() ? "; stopped by a signal" : "");
  return rest_requested() ? 128 + rest_signal() : 0;  // 130 for SIGINT, 143 for SIGTERM
}

}  // namespace
}  // namespace vimg::player_app

int main(int argc, char** argv) {
  using namespace vimg::player_app;
  const ArgsResult parsed = parse_player_args(std::vector<std::string>(argv + 1, argv + argc));
  if (!parsed.args) return parsed.exit_code;
  try {
    return run(*parsed.args);
  } catch (const std::exception& error) {
    std::fprintf(stderr, "vimg-player: %s\n", error.what());
    return 1;
  }
}
