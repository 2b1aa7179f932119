// `vimg compare` cost (issue 20: 20 images with the default exploration in <= 5 s on the project's
// machine): the whole comparison of 20 images of the bundled matching sets (60 x 110 mm, a 58 s
// exploration each), on both cores and on one, and its parts: one image's render under the
// exploration, the analysis of one signal (ST-SIM's and the discrimination model's), the ST-SIM
// matrix and the cue matrix of 20 signals.
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <vector>

#include "primitives/perception/discrimination_cues.hpp"
#include "primitives/perception/stsim.hpp"
#include "storage/image_io.hpp"
#include "study/compare.hpp"
#include "study/compare_render.hpp"
#include "study/exploration.hpp"

namespace {

using namespace vimg;
namespace fs = std::filesystem;

// The eight images of the bundled matching sets (assets/examples/set_*.vimg), copied under 20 names.
const std::vector<fs::path>& twenty_images() {
  static const std::vector<fs::path> paths = [] {
    std::vector<fs::path> sources;
    for (const auto& e : fs::directory_iterator(fs::path(VIMG_SOURCE_DIR) / "assets/examples")) {
      const std::string name = e.path().filename().string();
      if (name.rfind("set_", 0) == 0 && e.path().extension() == ".vimg") sources.push_back(e.path());
    }
    std::sort(sources.begin(), sources.end());
    const fs::path dir = fs::temp_directory_path() / ("vimg_compare_bench_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    std::vector<fs::path> out;
    for (int i = 0; i < 20; ++i) {
      const fs::path p = dir / ("image" + std::to_string(i) + ".vimg");
      fs::copy_file(sources[static_cast<std::size_t>(i) % sources.size()], p, fs::copy_options::overwrite_existing);
      out.push_back(p);
    }
    return out;
  }();
  return paths;
}

// The whole comparison: load, render and analyse on `threads` threads (0: every core), matrices.
void BM_Compare20(benchmark::State& state) {
  study::CompareRequest request;
  request.inputs = twenty_images();
  request.threads = static_cast<int>(state.range(0));
  for (auto _ : state) {
    const study::CompareResult r = study::run_compare(request);
    if (!r.ok()) state.SkipWithError("the comparison failed");
    benchmark::DoNotOptimize(r.predicted_confusion.data());
  }
}
BENCHMARK(BM_Compare20)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);

Image bundled(const char* name) {
  return *load_image_file(fs::path(VIMG_SOURCE_DIR) / "assets/examples" / name).image;
}

void BM_RenderOneImage(benchmark::State& state) {
  const Image image = bundled("set_b1_house_and_tree.vimg");
  const std::vector<Gesture> gestures{study::standard_exploration(image.width_mm, image.height_mm)->gesture};
  for (auto _ : state) {
    auto samples = study::render_for_compare(image, gestures, ResponseParams{});
    benchmark::DoNotOptimize(samples->data());
  }
}
BENCHMARK(BM_RenderOneImage)->Unit(benchmark::kMillisecond);

std::vector<double> rendered(const char* name) {
  const Image image = bundled(name);
  const std::vector<Gesture> gestures{study::standard_exploration(image.width_mm, image.height_mm)->gesture};
  const auto samples = study::render_for_compare(image, gestures, ResponseParams{});
  return std::vector<double>(samples->begin(), samples->end());
}

void BM_AnalyseOneSignal(benchmark::State& state) {
  const std::vector<double> signal = rendered("set_b1_house_and_tree.vimg");
  for (auto _ : state) {
    const StSimFeatures st = analyse_stsim(signal);
    const DiscriminationFeatures d = analyse_discrimination(signal);
    benchmark::DoNotOptimize(st.blocks);
    benchmark::DoNotOptimize(d.level_db);
  }
}
BENCHMARK(BM_AnalyseOneSignal)->Unit(benchmark::kMillisecond);

struct TwentySignals {
  std::vector<StSimFeatures> stsim;
  std::vector<DiscriminationFeatures> discrimination;
};

const TwentySignals& twenty_features() {
  static const TwentySignals features = [] {
    const char* names[] = {"set_a1_one_object.vimg", "set_a2_two_objects.vimg", "set_a3_three_objects.vimg",
                           "set_a4_four_objects.vimg", "set_b1_house_and_tree.vimg"};
    TwentySignals out;
    for (int i = 0; i < 20; ++i) {
      const std::vector<double> signal = rendered(names[i % 5]);
      out.stsim.push_back(analyse_stsim(signal));
      out.discrimination.push_back(analyse_discrimination(signal));
    }
    return out;
  }();
  return features;
}

void BM_StsimMatrix20(benchmark::State& state) {
  const auto& f = twenty_features();
  for (auto _ : state) benchmark::DoNotOptimize(stsim_matrix(f.stsim).data());
}
BENCHMARK(BM_StsimMatrix20)->Unit(benchmark::kMillisecond);

void BM_CueMatrix20(benchmark::State& state) {
  const auto& f = twenty_features();
  for (auto _ : state) benchmark::DoNotOptimize(cue_matrix(f.discrimination).data());
}
BENCHMARK(BM_CueMatrix20)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
