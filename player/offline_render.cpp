#include "player/offline_render.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "player/contact_mixer.hpp"
#include "player/gesture_playback.hpp"
#include "realtime/soft_limit.hpp"

namespace vimg {

namespace {

// Either source of finger steps: the exact gesture, or the simulated late panel.
template <class Source>
OfflineRenderResult render_steps(const Scene& scene, Source& playback, DriveSink& sink, const OfflineRenderOptions& options) {
  OfflineRenderResult result;
  const double rate = options.sample_rate_hz;
  const double dt = 1.0 / rate;
  ContactMixer mixer(options.max_contacts);
  mixer.set_scene(&scene);
  result.start_time_s = std::min(0.0, playback.start_time_s());
  const double end_s = playback.end_time_s();
  const double hard_end_s = end_s + std::max(0.0, options.max_tail_s);

  std::vector<FingerStep> steps;
  std::vector<float> block(std::max<std::size_t>(1, options.block_samples));
  sink.open(rate);
  std::uint64_t n = 0;
  bool done = false;
  while (!done) {
    if (options.should_stop && options.should_stop()) {
      result.interrupted = true;
      result.samples = n;
      return result;
    }
    const double block_start_s = result.start_time_s + static_cast<double>(n) * dt;
    std::size_t filled = 0;
    while (filled < block.size()) {
      const double t = result.start_time_s + static_cast<double>(n) * dt;
      // The first sample has no history: its step is empty.
      playback.steps_at(t, n == 0 ? 0.0 : dt, steps);
      const double d = mixer.step(steps, t, dt);
      const auto drive = static_cast<float>(soft_limit(d));
      block[filled++] = drive;
      ++n;
      if ((t >= end_s && steps.empty() && mixer.active_contacts() == 0) || t >= hard_end_s) {
        done = true;
        break;
      }
    }
    sink.write(std::span<const float>(block.data(), filled), block_start_s);
    if (options.progress) options.progress(block_start_s + static_cast<double>(filled) * dt, end_s, options.progress_context);
  }
  sink.close();
  result.samples = n;
  result.refused_contacts = mixer.refused_contacts();
  return result;
}

}  // namespace

OfflineRenderResult render_gesture(const Scene& scene, const Gesture& gesture, DriveSink& sink,
                                   const OfflineRenderOptions& options) {
  if (options.panel) {
    SimulatedPanel panel(gesture, *options.panel);
    return render_steps(scene, panel, sink, options);
  }
  GesturePlayback playback(gesture);
  return render_steps(scene, playback, sink, options);
}

}  // namespace vimg
