// `vimg compare IMAGE... [--actuator P] [--gesture G.csv]... --out REPORT.json|.html|.csv`: will
// people tell these images apart? (docs/studies.md, "Predicting confusion: vimg compare";
// study/compare.hpp does the work, study/compare_output.hpp writes the report).
#include <algorithm>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cli/command.hpp"
#include "cli/compare_inputs.hpp"
#include "hal/rest_on_exit.hpp"
#include "storage/gesture_csv.hpp"
#include "storage/atomic_file.hpp"
#include "storage/limits.hpp"
#include "storage/print_diagnostics.hpp"
#include "study/compare.hpp"
#include "study/compare_output.hpp"

namespace vimg::cli {

namespace {

struct CompareArgs {
  std::vector<std::string> inputs;
  std::string actuator;               // profile file; empty: the ideal actuator
  std::vector<std::string> gestures;  // empty: the standard exploration
  std::string model;                  // MODEL.json of vimg study fit; empty: the default constants
  std::string out;
};

constexpr const char* kProgram = "vimg compare";

int interrupted(const std::string& out) {
  std::fprintf(stderr, "%s: interrupted; %s not written\n", kProgram, out.c_str());
  return rest_signal() == SIGTERM ? cmdline::kExitSigterm : cmdline::kExitSigint;
}

// The gestures, each checked as `vimg render` checks its gesture; nothing after printing errors.
std::optional<std::vector<study::CompareGesture>> load_gestures(const std::vector<std::string>& files) {
  std::vector<study::CompareGesture> gestures;
  bool ok = true;
  for (const std::string& file : files) {
    GestureParseResult g = load_gesture_file(file);
    for (const std::string& e : g.errors) std::fprintf(stderr, "%s\n", e.c_str());
    if (!g.ok()) {
      ok = false;
      continue;
    }
    const double span_s = std::max(0.0, g.gesture->end_time_s()) - std::min(0.0, g.gesture->start_time_s());
    if (span_s > kMaxGestureDurationS) {
      std::fprintf(stderr, "%s: error: the render would last %.0f s from time 0 (limit %.0f s); shift the times to start near 0\n",
                   file.c_str(), span_s, kMaxGestureDurationS);
      ok = false;
      continue;
    }
    gestures.push_back({file, std::move(*g.gesture)});
  }
  if (!ok) return std::nullopt;
  return gestures;
}

int run_compare_command(const CompareArgs& a) {
  if (!study::is_compare_output(a.out))
    return usage_error(kProgram, "--out must end in .json, .html or .csv: '" + a.out + "'");
  if (a.inputs.size() < 2) return usage_error(kProgram, "give at least two images (or rendered signals) to compare");
  for (const std::string& in : a.inputs) {
    std::error_code ec;
    if (in == a.out || std::filesystem::equivalent(in, a.out, ec))
      return usage_error(kProgram, "--out names an input: '" + a.out + "'");
  }
  if (a.inputs.size() > kMaxCompareInputs)
    return usage_error(kProgram, std::to_string(a.inputs.size()) + " inputs (limit " + std::to_string(kMaxCompareInputs) + ")");

  study::CompareRequest request;
  for (const std::string& in : a.inputs) request.inputs.emplace_back(in);
  auto actuator = load_compare_actuator(a.actuator);
  if (!actuator) return kExitFailure;
  request.actuator = std::move(*actuator);
  if (!a.model.empty()) {
    const auto model = load_model_argument(a.model, request.actuator);
    if (!model) return kExitFailure;
    request.discrimination = model->constants;
  }
  auto gestures = load_gestures(a.gestures);
  if (!gestures) return kExitFailure;
  request.gestures = std::move(*gestures);

  // SIGINT/SIGTERM only set a flag; the renders stop at their next block and nothing is written.
  const SignalRestScope signals;
  request.should_stop = [] { return rest_requested(); };
  // Progress on stderr: a comparison of many images on a large canvas takes seconds.
  request.progress = [](std::size_t analysed, std::size_t total) {
    std::fprintf(stderr, "%s: %zu of %zu signals analysed\n", kProgram, analysed, total);
  };
  const study::CompareResult result = study::run_compare(request);
  print_diagnostics(result.diagnostics);
  if (result.interrupted || rest_requested()) return interrupted(a.out);
  if (!result.ok()) return kExitFailure;
  for (const std::string& w : result.warnings) std::fprintf(stderr, "%s: warning: %s\n", kProgram, w.c_str());
  const bool all_images = std::all_of(result.inputs.begin(), result.inputs.end(), [](const study::CompareInput& in) {
    return in.kind == study::CompareInputKind::image;
  });
  if (!result.warnings.empty() && all_images)
    std::fprintf(stderr,
                 "%s: `vimg separate` on these images proposes which tactile parameters to change, and how far, so "
                 "that people tell them apart (docs/separate.md)\n",
                 kProgram);
  // Written atomically; a signal that arrives before the rename still leaves nothing.
  // A new report takes the permission bits all the inputs share (one private image keeps it private).
  AtomicFileWriter file(a.out, NewFileMode::of_all({request.inputs.begin(), request.inputs.end()}));
  file.write(study::compare_output_text(a.out, result, a.model));
  if (rest_requested()) {
    file.abort();
    return interrupted(a.out);
  }
  const std::optional<std::string> error = file.ok() ? file.commit() : std::optional(file.error());
  if (error) {
    std::fprintf(stderr, "%s: %s\n", kProgram, error->c_str());
    return kExitFailure;
  }
  return kExitOk;
}

}  // namespace

void add_compare_command(CLI::App& vimg, int& exit_code) {
  CLI::App* sub = vimg.add_subcommand(
      "compare",
      "predict which images of a set people will confuse (level, pitch and envelope cues in JNDs, Shepard-Luce "
      "choice; ST-SIM reported)");
  sub->set_version_flag("--version", std::string(cmdline::version()), "print the version and exit");
  auto a = std::make_shared<CompareArgs>();
  sub->add_option("IMAGE", a->inputs,
                  "two or more .vimg or .png images of one canvas size, or rendered signals (.wav or .csv of vimg render at "
                  "8000 Hz), compared as they are")
      ->required();
  sub->add_option("--actuator", a->actuator,
                  "actuator profile: a file, or a shipped profile's name (lra-175hz-drv2605l, erm-10mm, voice-coil-audio, ideal): the images are felt as its predicted acceleration; default: ideal");
  sub->add_option("--gesture", a->gestures,
                  "a gesture CSV to render every image under, instead of the standard exploration; repeat it for several, "
                  "rendered one after another");
  sub->add_option("--model", a->model,
                  "MODEL.json of `vimg study fit`: the discrimination model's constants fitted on a study's trials "
                  "(default: the published figures' constants, docs/perception.md)");
  sub->add_option("--out", a->out,
                  "REPORT.json (matrices and warnings), REPORT.html (self-contained, heat maps) or REPORT.csv (one row per "
                  "pair: image_i,image_j,stsim,level_jnd,pitch_jnd,envelope_jnd,distance_jnd,predicted_p), written atomically")
      ->required();
  sub->footer(
      "Default exploration (docs/studies.md): horizontal and vertical serpentine passes 10 mm apart over the whole canvas at "
      "40, 100 and 250 mm/s. Pairs likely confused are printed as warnings. At most " +
      std::to_string(kMaxCompareInputs) + " inputs. SIGINT/SIGTERM write nothing and exit 130/143.");
  sub->callback([a, &exit_code] { exit_code = run_compare_command(*a); });
}

}  // namespace vimg::cli
