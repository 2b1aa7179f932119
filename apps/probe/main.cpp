// vimg-probe: explore a volume scene with the mouse, or watch the scene's haptic loop run on a
// force device (docs/volume-probe.md, "Virtual probe"; see --help).
//   vimg-probe SCENE [--frames N] [--move X_MM,Z_MM] [--screenshot OUT.bmp]
//   vimg-probe SCENE --device sim|hid[:PATH] [--path P.csv] [--frames N] [--screenshot OUT.bmp]
// The window shows the slice y = const of the scene's first scalar data (x across, z down), the
// flow of its first vector data as ticks, the probe (white), and the kinaesthetic force (red
// line, 20 px/N). The mouse moves the probe in the slice; the wheel moves the slice in y. The
// vibrotactile part plays on the default audio output (1 N = full scale). --frames, --move and
// --screenshot run a fixed number of frames with the probe at a given point and save the window,
// for tests under SDL's dummy drivers.
#include <SDL.h>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <memory>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "apps/probe/probe_args.hpp"
#include "apps/probe/probe_session.hpp"
#include "cmdline/exit_codes.hpp"
#include "hal/force/force_device_opener.hpp"
#include "hal/rest_on_exit.hpp"
#include "player/render_defaults.hpp"
#include "storage/print_diagnostics.hpp"
#include "storage/volume/volume_scene_io.hpp"

namespace {

using vimg::Vec3;

constexpr int kPxPerMm = 5;
constexpr double kAudioRate = vimg::kDefaultRenderRateHz;  // the audio sink runs at the render rate

struct View {
  Vec3 lo_mm, hi_mm;  // the workspace box
  int width = 0, height = 0;
  double y_mm = 0.0;  // the slice
  Vec3 to_world_m(int px, int py) const {
    return Vec3{lo_mm.x + double(px) / kPxPerMm, y_mm, lo_mm.z + double(py) / kPxPerMm} * 1e-3;
  }
  SDL_Point to_screen(const Vec3& p_m) const {
    return {static_cast<int>(std::lround((p_m.x * 1e3 - lo_mm.x) * kPxPerMm)),
            static_cast<int>(std::lround((p_m.z * 1e3 - lo_mm.z) * kPxPerMm))};
  }
};

void draw_slice(SDL_Renderer* r, const View& v, const vimg::ScalarGrid* scalar, const vimg::VectorGrid* vector) {
  if (scalar) {
    double lo = 1e300, hi = -1e300;
    for (float x : scalar->values()) lo = std::min(lo, double(x)), hi = std::max(hi, double(x));
    const double span = hi > lo ? hi - lo : 1.0;
    for (int py = 0; py < v.height; py += 2) {
      for (int px = 0; px < v.width; px += 2) {
        const double value = scalar->value(v.to_world_m(px, py));
        const auto g = static_cast<Uint8>(std::clamp(40.0 + 180.0 * (value - lo) / span, 0.0, 255.0));
        SDL_SetRenderDrawColor(r, g, g, static_cast<Uint8>(std::min(255, g + 20)), 255);
        SDL_Rect cell{px, py, 2, 2};
        SDL_RenderFillRect(r, &cell);
      }
    }
  }
  if (vector) {
    SDL_SetRenderDrawColor(r, 90, 200, 120, 255);
    for (int py = 10; py < v.height; py += 40) {
      for (int px = 10; px < v.width; px += 40) {
        const Vec3 d = vimg::normalized(vector->vector(v.to_world_m(px, py)));
        SDL_RenderDrawLine(r, px, py, px + static_cast<int>(14 * d.x), py + static_cast<int>(14 * d.z));
        SDL_RenderDrawPoint(r, px, py);
      }
    }
  }
}

int fail(const std::string& message) {
  std::fprintf(stderr, "vimg-probe: %s\n", message.c_str());
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  const vimg::probe::ProbeArgsResult parsed = vimg::probe::parse_probe_args(argc, argv);
  if (!parsed.args) return parsed.exit_code;
  const vimg::probe::ProbeArgs& args = *parsed.args;
  const std::string& scene_path = args.scene_path;
  const std::string& screenshot = args.screenshot;
  const int frames = args.frames;
  const bool scripted_move = args.move_mm.has_value();
  const double move_x = scripted_move ? args.move_mm->first : 0.0;
  const double move_z = scripted_move ? args.move_mm->second : 0.0;
  vimg::VolumeSceneLoadOptions load_options;
  load_options.allow_files_outside_scene_folder = args.allow_outside_files;
  vimg::VolumeSceneLoadResult loaded = vimg::load_volume_scene_file(scene_path, load_options);
  vimg::print_diagnostics(loaded.diagnostics);
  if (!loaded.ok()) return 1;
  const vimg::VolumeScene& scene = loaded.loaded->scene;
  const vimg::ScalarGrid* scalar = loaded.loaded->scalars.empty() ? nullptr : loaded.loaded->scalars.begin()->second.get();
  const vimg::VectorGrid* vector = loaded.loaded->vectors.empty() ? nullptr : loaded.loaded->vectors.begin()->second.get();
  Vec3 audio_axis{0.0, 0.0, 1.0};
  if (!scene.roughness.empty()) audio_axis = vimg::normalized(scene.roughness.front().direction);
  else if (!scene.transition_cues.empty()) audio_axis = vimg::normalized(scene.transition_cues.front().direction);

  View view;
  view.lo_mm = scene.device.workspace_mm * -0.5;
  view.hi_mm = scene.device.workspace_mm * 0.5;
  view.width = static_cast<int>(scene.device.workspace_mm.x * kPxPerMm);
  view.height = static_cast<int>(scene.device.workspace_mm.z * kPxPerMm);

  // Device mode: the scene's haptic loop runs on the force device, as in vimg-force; the window
  // shows what the loop reads and sends. SIGINT/SIGTERM stop it (zero force first).
  std::unique_ptr<vimg::ForceDevice> device;
  std::unique_ptr<vimg::HapticLoop> loop;
  std::string device_description;
  const vimg::SignalRestScope signals;
  if (!args.device.empty()) {
    std::vector<vimg::Diagnostic> problems;
    std::optional<std::vector<vimg::HandPathPoint>> hand = vimg::simulated_hand_path(args.path_file, problems);
    vimg::print_diagnostics(problems);
    if (!hand) return 1;
    vimg::OpenedForceDevice opened = vimg::open_force_device(
        args.device, scene.device, std::move(*hand),
        args.path_file.empty() ? "the hand at rest at the workspace centre" : "the hand on " + args.path_file);
    if (!opened.device) return fail(opened.error);
    device = std::move(opened.device);
    device_description = opened.description;
    loop = std::make_unique<vimg::HapticLoop>(*device, vimg::haptic_loop_config(scene.device, args.realtime_priority));
    loop->submit_scene(vimg::build_haptic_scene(*loaded.loaded));
    if (!loop->start()) return fail("cannot start the haptic loop at the scene's rate (100..4000 Hz)");
  }

  if (SDL_Init(SDL_INIT_VIDEO) != 0) return fail(std::string("SDL: ") + SDL_GetError());
  SDL_Window* window = SDL_CreateWindow("vimg-probe", SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED, view.width, view.height, 0);
  if (!window) return fail(std::string("SDL window: ") + SDL_GetError());
  SDL_Renderer* renderer = SDL_CreateRenderer(window, -1, SDL_RENDERER_SOFTWARE);
  if (!renderer) return fail(std::string("SDL renderer: ") + SDL_GetError());
  SDL_Texture* slice = SDL_CreateTexture(renderer, SDL_PIXELFORMAT_ARGB8888, SDL_TEXTUREACCESS_TARGET, view.width, view.height);

  // Audio is optional: without a device the probe still shows the forces.
  SDL_AudioDeviceID audio = 0;
  if (!loop && SDL_InitSubSystem(SDL_INIT_AUDIO) == 0) {
    SDL_AudioSpec want{}, have{};
    want.freq = static_cast<int>(kAudioRate);
    want.format = AUDIO_F32SYS;
    want.channels = 1;
    want.samples = 256;
    audio = SDL_OpenAudioDevice(nullptr, 0, &want, &have, 0);
    if (audio) SDL_PauseAudioDevice(audio, 0);
    else std::fprintf(stderr, "vimg-probe: no audio output (%s); forces are shown only\n", SDL_GetError());
  }

  vimg::probe::ProbeSession session(vimg::build_haptic_scene(*loaded.loaded), kAudioRate, scene.device.max_force_N, {});
  bool slice_dirty = true, running = true;
  Uint64 last = SDL_GetPerformanceCounter();
  std::vector<float> samples;
  samples.reserve(4096);
  int mouse_x = view.width / 2, mouse_y = view.height / 2;
  for (int frame = 0; running; ++frame) {
    SDL_Event e;
    while (SDL_PollEvent(&e)) {
      if (e.type == SDL_QUIT || (e.type == SDL_KEYDOWN && e.key.keysym.sym == SDLK_ESCAPE)) running = false;
      else if (e.type == SDL_MOUSEMOTION) mouse_x = e.motion.x, mouse_y = e.motion.y;
      else if (e.type == SDL_MOUSEWHEEL) {
        view.y_mm = std::clamp(view.y_mm + 2.0 * e.wheel.y, view.lo_mm.y, view.hi_mm.y);
        slice_dirty = true;
      }
    }
    if (scripted_move) {
      mouse_x = static_cast<int>((move_x - view.lo_mm.x) * kPxPerMm);
      mouse_y = static_cast<int>((move_z - view.lo_mm.z) * kPxPerMm);
    }
    if (vimg::rest_requested()) break;
    const Uint64 now = SDL_GetPerformanceCounter();
    const double elapsed = frames > 0 ? 1.0 / 60.0 : std::min(0.1, double(now - last) / double(SDL_GetPerformanceFrequency()));
    last = now;
    samples.clear();
    vimg::probe::ProbeForces f = session.latest();
    vimg::HapticLoopStatus status;
    if (loop) {
      if (frames > 0) SDL_Delay(16);  // scripted: about 60 frames a second of the running loop
      status = loop->status();
      if (!loop->running()) break;  // a fault: reported below
      // The slice follows the probe (redrawn when it moves by a millimetre or more).
      if (std::abs(status.position_m.y * 1e3 - view.y_mm) >= 1.0) {
        view.y_mm = std::clamp(status.position_m.y * 1e3, view.lo_mm.y, view.hi_mm.y);
        slice_dirty = true;
      }
      f = {status.position_m, status.force_N, Vec3{}, status.force_N};
    } else {
      session.advance(elapsed, view.to_world_m(mouse_x, mouse_y), audio_axis, samples);
      f = session.latest();
    }
    if (audio) {
      // Keep at most 60 ms queued: a late vibration is worse than none.
      if (SDL_GetQueuedAudioSize(audio) > static_cast<Uint32>(0.06 * kAudioRate * sizeof(float))) SDL_ClearQueuedAudio(audio);
      for (auto& s : samples) s = std::clamp(s, -1.0f, 1.0f);
      SDL_QueueAudio(audio, samples.data(), static_cast<Uint32>(samples.size() * sizeof(float)));
    }

    if (slice_dirty && slice) {
      SDL_SetRenderTarget(renderer, slice);
      SDL_SetRenderDrawColor(renderer, 0, 0, 0, 255);
      SDL_RenderClear(renderer);
      draw_slice(renderer, view, scalar, vector);
      SDL_SetRenderTarget(renderer, nullptr);
      slice_dirty = false;
    }
    SDL_RenderCopy(renderer, slice, nullptr, nullptr);
    const SDL_Point p = view.to_screen(f.position_m);
    SDL_SetRenderDrawColor(renderer, 230, 60, 50, 255);
    SDL_RenderDrawLine(renderer, p.x, p.y, p.x + static_cast<int>(20 * f.kinaesthetic_N.x * kPxPerMm),
                       p.y + static_cast<int>(20 * f.kinaesthetic_N.z * kPxPerMm));
    SDL_SetRenderDrawColor(renderer, 255, 255, 255, 255);
    SDL_Rect probe_box{p.x - 3, p.y - 3, 7, 7};
    SDL_RenderFillRect(renderer, &probe_box);
    // The vibrotactile magnitude as a bar along the bottom edge (full width = 1 N).
    SDL_SetRenderDrawColor(renderer, 250, 200, 60, 255);
    SDL_Rect bar{0, view.height - 6, static_cast<int>(std::min(1.0, vimg::norm(f.vibrotactile_N)) * view.width), 6};
    SDL_RenderFillRect(renderer, &bar);
    char title[200];
    if (loop) {
      std::snprintf(title, sizeof title, "vimg-probe  %s  %s  %.0f Hz  p99 %.0f us  x %.1f  y %.1f  z %.1f mm   |F| sent %.2f N",
                    args.device.c_str(), vimg::describe(status.state), status.timing.rate_hz, status.timing.jitter_p99_us,
                    f.position_m.x * 1e3, f.position_m.y * 1e3, f.position_m.z * 1e3, vimg::norm(f.total_N));
    } else {
      std::snprintf(title, sizeof title, "vimg-probe  x %.1f  y %.1f  z %.1f mm   |F| %.2f N  kin %.2f N  vib %.2f N",
                    f.position_m.x * 1e3, f.position_m.y * 1e3, f.position_m.z * 1e3, vimg::norm(f.total_N),
                    vimg::norm(f.kinaesthetic_N), vimg::norm(f.vibrotactile_N));
    }
    SDL_SetWindowTitle(window, title);
    if (frames > 0 && frame == frames - 1 && !screenshot.empty()) {
      SDL_Surface* shot = SDL_CreateRGBSurfaceWithFormat(0, view.width, view.height, 32, SDL_PIXELFORMAT_ARGB8888);
      if (!shot || SDL_RenderReadPixels(renderer, nullptr, SDL_PIXELFORMAT_ARGB8888, shot->pixels, shot->pitch) != 0 ||
          SDL_SaveBMP(shot, screenshot.c_str()) != 0) {
        return fail(std::string("cannot save the screenshot: ") + SDL_GetError());
      }
      SDL_FreeSurface(shot);
    }
    SDL_RenderPresent(renderer);
    if (frames > 0 && frame + 1 >= frames) break;
    if (frames == 0) SDL_Delay(5);
  }
  int code = 0;
  if (loop) {
    loop->stop();  // zero force before anything else
    const vimg::HapticLoopStatus end = loop->status();
    std::printf("vimg-probe: %s: %llu cycles at %.1f Hz, max |F| %.3f N, %s\n", device_description.c_str(),
                static_cast<unsigned long long>(end.cycles), end.timing.rate_hz, end.max_force_N, vimg::describe(end.state));
    if (loop->failed()) {
      std::fprintf(stderr, "vimg-probe: error: device fault: %s\n", loop->fault_text().c_str());
      code = 1;
    }
  }
  if (vimg::rest_requested()) code = vimg::rest_signal() == SIGTERM ? vimg::cmdline::kExitSigterm : vimg::cmdline::kExitSigint;
  if (audio) SDL_CloseAudioDevice(audio);
  SDL_DestroyTexture(slice);
  SDL_DestroyRenderer(renderer);
  SDL_DestroyWindow(window);
  SDL_Quit();
  return code;
}
