// The native cost per sample of the path the web page's renderGesture runs in WebAssembly
// (web/wasm/web_renderer.cpp): parse the gesture CSV, render it through the actuator chain at
// 48 kHz into memory. Compare with `node bench/web_render_bench.mjs` on the same image, gestures
// and profile (docs/benchmarks/web-and-wasm.md, "WebAssembly render"): the ratio is wasm / native.
#include <benchmark/benchmark.h>

#include <string>

#include "storage/actuator_profile.hpp"
#include "player/actuator_sink.hpp"
#include "player/drive_sinks.hpp"
#include "storage/gesture_csv.hpp"
#include "player/offline_render.hpp"
#include "player/scene.hpp"
#include "storage/image_io.hpp"
#include "storage/read_file.hpp"

namespace {

using namespace vimg;

const char* const kGestures[] = {"smiley_circle_240hz.csv", "smiley_eyes.csv", "smiley_two_fingers.csv"};
const char* const kProfiles[] = {"ideal", "lra-175hz-drv2605l"};

// state.range(0): gesture, state.range(1): profile.
void BM_RenderGestureNative(benchmark::State& state) {
  const std::string root = VIMG_SOURCE_DIR "/assets/";
  const LoadResult image = load_image_file(root + "examples/smiley.vimg");
  const std::string gesture_path = root + "gestures/" + kGestures[state.range(0)];
  const FileReadResult csv = read_regular_file(gesture_path, 64u << 20);
  const ProfileLoadResult profile = load_actuator_profile(root + "profiles/" + kProfiles[state.range(1)] + ".xml");
  if (!image.ok() || !csv.bytes || !profile.profile) {
    state.SkipWithError("cannot load the smiley, the gesture or the profile");
    return;
  }
  SceneOptions scene_options;
  scene_options.carrier_frequency_hz = profile.profile->resonance_hz;
  const auto scene = compile_scene(*image.image, scene_options);
  OfflineRenderOptions options;
  options.sample_rate_hz = 48000.0;
  std::size_t samples = 0;
  for (auto _ : state) {
    const GestureParseResult gesture = parse_gesture_csv(*csv.bytes, gesture_path);
    MemorySink memory;
    ActuatorSink shaped(memory, profile.profile->response, OutputSignal::drive, false);
    render_gesture(*scene, *gesture.gesture, shaped, options);
    samples += memory.samples().size();
    benchmark::DoNotOptimize(memory.samples().data());
  }
  state.SetLabel(std::string(kGestures[state.range(0)]) + " " + kProfiles[state.range(1)]);
  state.counters["ns_per_sample"] = benchmark::Counter(
      static_cast<double>(samples), benchmark::Counter::kIsRate | benchmark::Counter::kInvert,
      benchmark::Counter::OneK::kIs1000);
}
BENCHMARK(BM_RenderGestureNative)->ArgsProduct({{0, 1, 2}, {0, 1}})->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
