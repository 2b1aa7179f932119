// The touch predictor (primitives/touch_prediction/): its cost per event and per prediction, and,
// with --table DIR, the published protocol's table on the shared traces and the felt onset error
// of the latency scenario (docs/latency.md, docs/benchmarks/touch-prediction.md):
//   build/release/bench/touch_prediction_bench --table tests/data/touch-latency-henze2017
//   build/release/bench/touch_prediction_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "bench/henze_traces.hpp"
#include "bench/latency_scenario.hpp"
#include "primitives/touch_prediction/circling_finger.hpp"
#include "primitives/touch_prediction/prediction_protocol.hpp"

namespace vimg {
namespace {

void BM_Predict(benchmark::State& state) {
  const FingerHistory h = circling_finger_history();
  const auto model = static_cast<TouchPredictionModel>(state.range(0));
  double horizon_s = 0.033;
  for (auto _ : state) {
    const PredictedPosition p = predict_finger(h, horizon_s, model);
    benchmark::DoNotOptimize(p);
    horizon_s = next_bench_horizon_s(horizon_s);
  }
  state.SetLabel(std::string(touch_prediction_model_name(model)));
}
BENCHMARK(BM_Predict)->Arg(0)->Arg(1)->Arg(2)->Arg(3);

void BM_AddEvent(benchmark::State& state) {
  FingerHistory h = circling_finger_history();
  double t = 1.0;
  for (auto _ : state) {
    t += 1.0 / 240.0;
    add_finger_event(h, t, t * 100.0, 5.0);
    benchmark::DoNotOptimize(h);
  }
}
BENCHMARK(BM_AddEvent);

using henze_traces::kPxPerMm;
using henze_traces::task_strokes;

int print_tables(const std::string& dir) {
  struct Task {
    const char* name;
    const char* prefix;
  };
  // In sample for fitted and learned (both were made from these traces); the out-of-sample table is
  // scripts/train_touch_predictor.py's (docs/latency.md).
  std::printf("| task | horizon | samples | no extrapolation | linear (authors) | linear (ours, in time) | fitted | learned | "
              "fitted / none | learned / none |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|\n");
  for (const Task& task : {Task{"writing", "WriteTasks"}, Task{"drawing", "PaintTasks"}, Task{"Fitts", "FittsTasks"}}) {
    const std::vector<TouchStroke> strokes = task_strokes(dir, task.prefix);
    if (strokes.empty()) return 1;
    for (int s : {2, 4, 6}) {
      const ProtocolErrors e = evaluate_prediction_protocol(strokes, s);
      std::printf("| %s | %.0f ms | %zu | %.1f px | %.1f px | %.1f px | %.1f px | %.1f px | %.3f | %.3f |\n", task.name,
                  s * 1000.0 / 60.0, e.samples, e.none_mm * kPxPerMm, e.authors_linear_mm * kPxPerMm,
                  e.model_mm[1] * kPxPerMm, e.model_mm[2] * kPxPerMm, e.model_mm[3] * kPxPerMm, e.model_mm[2] / e.none_mm,
                  e.model_mm[3] / e.none_mm);
    }
  }
  using namespace latency_scenario;
  const Gesture g = curved_swipe();
  const std::vector<double> exact = onsets(g, std::nullopt);
  std::printf("\n| panel latency | felt onset error, late | compensated (fitted) | compensated (linear) | compensated (learned) |\n"
              "|---|---|---|---|---|\n");
  for (double latency_s : {0.03, 0.06, 0.1}) {
    const double late = mean_onset_error_mm(exact, onsets(g, PanelSimulation{latency_s, false}), kSpeed_mm_per_s);
    const double fitted = mean_onset_error_mm(
        exact, onsets(g, PanelSimulation{latency_s, true, TouchPredictionModel::fitted}), kSpeed_mm_per_s);
    const double linear = mean_onset_error_mm(
        exact, onsets(g, PanelSimulation{latency_s, true, TouchPredictionModel::linear}), kSpeed_mm_per_s);
    const double learned = mean_onset_error_mm(
        exact, onsets(g, PanelSimulation{latency_s, true, TouchPredictionModel::learned}), kSpeed_mm_per_s);
    std::printf("| %.0f ms | %.2f mm | %.2f mm | %.2f mm | %.2f mm |\n", latency_s * 1e3, late, fitted, linear, learned);
  }
  return 0;
}

}  // namespace
}  // namespace vimg

int main(int argc, char** argv) {
  if (argc == 3 && std::strcmp(argv[1], "--table") == 0) return vimg::print_tables(argv[2]);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
