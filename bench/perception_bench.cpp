// What `vimg compare` costs in the perceptual model (docs/perception.md): 20 rendered signals of
// 20 s at 8 kHz, each analysed once (ST-SIM's features and the discrimination model's), then ST-SIM
// both ways and the cue distances for every pair, and the predicted confusion.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

#include "primitives/perception/discrimination_choice.hpp"
#include "primitives/perception/identification_choice.hpp"
#include "primitives/perception/predicted_confusion.hpp"
#include "primitives/perception/stsim.hpp"
#include "primitives/random/splitmix64.hpp"

namespace vimg {
namespace {

constexpr double kRateHz = 8000.0;
constexpr double kSeconds = 20.0;
constexpr std::size_t kSignals = 20;

// Signal i: textures of several frequencies and levels, touched 0.5 s of every 0.8 s, with DOT-like
// bursts and a little noise, so that no two are alike and silent stretches occur.
std::vector<double> make_signal(std::size_t i) {
  std::vector<double> x(static_cast<std::size_t>(kSeconds * kRateHz));
  const double texture_hz = 40.0 + 15.0 * static_cast<double>(i);
  const double gain = 0.2 + 0.04 * static_cast<double>(i);
  SplitMix64 random(i);
  for (std::size_t n = 0; n < x.size(); ++n) {
    const double t = static_cast<double>(n) / kRateHz;
    const double phase = std::fmod(t, 0.8);
    const double noise = 0.01 * (random.unit() - 0.5);
    double v = phase < 0.5 ? gain * std::sin(2.0 * std::numbers::pi * texture_hz * t) : 0.0;
    if (i % 3 == 0 && phase > 0.6 && phase < 0.63) v += std::sin(2.0 * std::numbers::pi * 175.0 * (phase - 0.6));
    x[n] = v + noise;
  }
  return x;
}

const std::vector<std::vector<double>>& signals() {
  static const std::vector<std::vector<double>> s = [] {
    std::vector<std::vector<double>> all;
    for (std::size_t i = 0; i < kSignals; ++i) all.push_back(make_signal(i));
    return all;
  }();
  return s;
}

struct Features {
  std::vector<StSimFeatures> stsim;
  std::vector<DiscriminationFeatures> discrimination;
};

Features analyse_all() {
  Features f;
  for (const auto& s : signals()) {
    f.stsim.push_back(analyse_stsim(s));
    f.discrimination.push_back(analyse_discrimination(s));
  }
  return f;
}

// Both analyses of 20 signals of 20 s.
void BM_AnalyseTwentySignals(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(analyse_all());
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(kSignals));
}
BENCHMARK(BM_AnalyseTwentySignals)->Unit(benchmark::kMillisecond);

// stsim[i][j] for all 380 ordered pairs.
void BM_StSimMatrixTwentySignals(benchmark::State& state) {
  const auto features = analyse_all();
  for (auto _ : state) benchmark::DoNotOptimize(stsim_matrix(features.stsim));
}
BENCHMARK(BM_StSimMatrixTwentySignals)->Unit(benchmark::kMillisecond);

// cue_distances for all 190 pairs.
void BM_CueMatrixTwentySignals(benchmark::State& state) {
  const auto features = analyse_all();
  for (auto _ : state) benchmark::DoNotOptimize(cue_matrix(features.discrimination));
}
BENCHMARK(BM_CueMatrixTwentySignals)->Unit(benchmark::kMillisecond);

// Identification alone (identification_choice.hpp, O(n^3)) on the twenty signals' cue matrix.
void BM_IdentificationTwentySignals(benchmark::State& state) {
  const CueMatrix cues = cue_matrix(analyse_all().discrimination);
  for (auto _ : state) benchmark::DoNotOptimize(identification_confusion(cues));
}
BENCHMARK(BM_IdentificationTwentySignals)->Unit(benchmark::kMillisecond);

// Everything `vimg compare` asks of the model after rendering: analyse, both matrices, confusion.
void BM_CompareTwentySignals(benchmark::State& state) {
  for (auto _ : state) {
    const auto features = analyse_all();
    benchmark::DoNotOptimize(stsim_matrix(features.stsim));
    const PerceptionMatrix p = identification_confusion(cue_matrix(features.discrimination));
    benchmark::DoNotOptimize(likely_confused_pairs(p));
  }
}
BENCHMARK(BM_CompareTwentySignals)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace vimg
BENCHMARK_MAIN();
