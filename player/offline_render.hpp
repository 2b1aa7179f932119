#pragma once
// Offline rendering: the same engine as the real-time thread, run as fast as possible. Used by
// `vimg render` and the tests.
#include <cstddef>
#include <cstdint>
#include <optional>

#include "player/drive_sink.hpp"
#include "primitives/gesture.hpp"
#include "player/render_defaults.hpp"
#include "player/scene.hpp"
#include "player/simulated_panel.hpp"

namespace vimg {

struct OfflineRenderOptions {
  double sample_rate_hz = kDefaultRenderRateHz;  // kMinRenderRateHz .. kMaxRenderRateHz
  std::size_t block_samples = 64;
  std::size_t max_contacts = 512;
  // After the gesture ends, rendering goes on until every ring-down has finished, at most this long.
  double max_tail_s = 10.0;
  // Asked before every block (e.g. "has SIGINT arrived?"); true ends the render at once, without
  // closing the sink, so that the caller can abandon the output. Null: never.
  bool (*should_stop)() = nullptr;
  // Set: the gesture reaches the renderer through a simulated late panel and the live tracker's
  // compensation (player/simulated_panel.hpp) instead of exactly. Check panel_simulation_problem().
  std::optional<PanelSimulation> panel;
  // Called after each block with the time rendered so far and the time the gesture ends (for
  // progress on long renders). Null: never.
  void (*progress)(double rendered_s, double end_s, void* context) = nullptr;
  void* progress_context = nullptr;
};

struct OfflineRenderResult {
  std::uint64_t samples = 0;
  double start_time_s = 0.0;  // time of the first sample (the gesture's start, or 0 if later)
  std::uint64_t refused_contacts = 0;
  bool interrupted = false;  // should_stop() said so; the sink was not closed
};

// Samples are at start_time_s + n / rate. Calls sink.open(), write() per block, then close()
// (unless interrupted).
OfflineRenderResult render_gesture(const Scene& scene, const Gesture& gesture, DriveSink& sink,
                                   const OfflineRenderOptions& options = {});

}  // namespace vimg
