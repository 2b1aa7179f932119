#include "study/compare_render.hpp"

#include <algorithm>
#include <cmath>

#include "player/actuator_sink.hpp"
#include "player/drive_sinks.hpp"
#include "player/offline_render.hpp"
#include "player/scene.hpp"
#include "storage/signal_file.hpp"

namespace vimg::study {

namespace {

// Samples from min(0, start) to end + tail, as render_gesture numbers them.
std::size_t gesture_samples(const Gesture& g) {
  const double span_s = g.end_time_s() + kCompareTailS - std::min(0.0, g.start_time_s());
  return static_cast<std::size_t>(std::ceil(span_s * kCompareRateHz - 1e-9));
}

}  // namespace

std::size_t compare_render_samples(const std::vector<Gesture>& gestures) {
  std::size_t n = 0;
  for (const Gesture& g : gestures) n += gesture_samples(g);
  return n;
}

std::optional<std::vector<float>> render_for_compare(const Image& image, const std::vector<Gesture>& gestures,
                                                     const ResponseParams& response, bool (*should_stop)()) {
  SceneOptions scene_options;
  scene_options.carrier_frequency_hz = response.resonance_hz;
  const auto scene = compile_scene(image, scene_options);
  std::size_t longest = 0;
  for (const Gesture& g : gestures) longest = std::max(longest, gesture_samples(g));
  std::vector<float> out;
  out.reserve(compare_render_samples(gestures));
  MemorySink memory(longest + 64);
  for (const Gesture& g : gestures) {
    ActuatorSink acceleration(memory, response, OutputSignal::acceleration, false);
    OfflineRenderOptions options;
    options.sample_rate_hz = kCompareRateHz;
    options.max_tail_s = kCompareTailS;
    options.should_stop = should_stop;
    const OfflineRenderResult r = render_gesture(*scene, g, acceleration, options);
    if (r.interrupted) return std::nullopt;
    const std::size_t want = gesture_samples(g);
    const std::vector<float>& got = memory.samples();
    const std::size_t keep = std::min(want, got.size());
    out.insert(out.end(), got.begin(), got.begin() + static_cast<std::ptrdiff_t>(keep));
    out.resize(out.size() + (want - keep), 0.0f);
  }
  return out;
}

}  // namespace vimg::study
