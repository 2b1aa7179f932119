// Actuator response model: CPU time per output sample of each model, of the equalizer and of the
// whole chain (`vimg render --signal acceleration --equalize`), against the 125 us sample period at
// 8 kHz. Goal: at most 1 % of the period (1.25 us), so the model fits the render thread.
#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "primitives/actuator/actuator_chain.hpp"
#include "primitives/actuator/actuator_model.hpp"
#include "primitives/actuator/equalizer.hpp"

namespace vimg {
namespace {

constexpr double kRate = 8000.0;

// One second of a 175 Hz carrier with a 20 Hz texture on it, the kind of drive a render makes.
std::vector<float> drive_signal() {
  std::vector<float> x(8000);
  for (std::size_t n = 0; n < x.size(); ++n) {
    const double t = static_cast<double>(n) / kRate;
    x[n] = static_cast<float>(0.8 * std::sin(2.0 * std::numbers::pi * 175.0 * t) * (0.6 + 0.4 * std::sin(2.0 * std::numbers::pi * 20.0 * t)));
  }
  return x;
}

ResponseParams params_for(int model) {
  ResponseParams p;
  p.model = static_cast<ResponseModel>(model);
  return p;
}

const char* name_of(int model) {
  switch (static_cast<ResponseModel>(model)) {
    case ResponseModel::ideal: return "ideal";
    case ResponseModel::lra: return "lra";
    case ResponseModel::erm: return "erm";
    case ResponseModel::voice_coil: return "voice_coil";
  }
  return "?";
}

void BM_ModelPerSample(benchmark::State& state) {
  const auto model_index = static_cast<int>(state.range(0));
  state.SetLabel(name_of(model_index));
  ActuatorModel model(params_for(model_index), kRate);
  const std::vector<float> x = drive_signal();
  for (auto _ : state) {
    double sum = 0.0;
    for (const float v : x) sum += model.process(v);
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(x.size()));
}
BENCHMARK(BM_ModelPerSample)
    ->Arg(static_cast<int>(ResponseModel::ideal))
    ->Arg(static_cast<int>(ResponseModel::lra))
    ->Arg(static_cast<int>(ResponseModel::erm))
    ->Arg(static_cast<int>(ResponseModel::voice_coil));

void BM_EqualizedLraChainPerSample(benchmark::State& state) {
  ActuatorChain chain(params_for(static_cast<int>(ResponseModel::lra)), kRate, OutputSignal::acceleration, true);
  const std::vector<float> x = drive_signal();
  for (auto _ : state) {
    float sum = 0.0f;
    for (const float v : x) sum += chain.process(v);
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(x.size()));
}
BENCHMARK(BM_EqualizedLraChainPerSample);

// Designing a model (done once per render or profile change, not per sample).
void BM_DesignVoiceCoil(benchmark::State& state) {
  for (auto _ : state) {
    ActuatorModel model(params_for(static_cast<int>(ResponseModel::voice_coil)), kRate);
    benchmark::DoNotOptimize(model);
  }
}
BENCHMARK(BM_DesignVoiceCoil);

}  // namespace
}  // namespace vimg

BENCHMARK_MAIN();
