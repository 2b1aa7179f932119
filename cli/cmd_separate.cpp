// `vimg separate IMAGE... --actuator A --out DIR [--model M] [--target P] [--vary LIST] [--keep IMAGE]...`:
// what to change so that people tell a set apart (docs/separate.md; study/separate.hpp does the
// work, study/separate_output.hpp writes the report).
//
// Exit status: 0 the target is reached (the proposal written) or was already (nothing written);
// 3 the target is out of reach (the best set found written, with what limits it); 1 bad input
// (an image or file that does not load, an output folder that cannot be made); 2 usage; 130/143
// interrupted (nothing half written).
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cli/command.hpp"
#include "cli/compare_inputs.hpp"
#include "cli/felt_report.hpp"
#include "hal/rest_on_exit.hpp"
#include "storage/atomic_file.hpp"
#include "storage/image_io.hpp"
#include "storage/limits.hpp"
#include "storage/print_diagnostics.hpp"
#include "study/separate.hpp"
#include "study/separate_output.hpp"

namespace vimg::cli {

namespace {

constexpr const char* kProgram = "vimg separate";
constexpr int kExitOutOfReach = 3;

struct SeparateArgs {
  std::vector<std::string> inputs;
  std::string actuator;
  std::string model;
  std::string out;
  double target = study::kIdentifiedTarget;
  std::string vary;
  std::vector<std::string> keep;
  int threads = 0;
};

int interrupted() {
  std::fprintf(stderr, "%s: interrupted; no file half written\n", kProgram);
  return rest_signal() == SIGTERM ? cmdline::kExitSigterm : cmdline::kExitSigint;
}

bool same_file(const std::string& a, const std::string& b) {
  std::error_code ec;
  return a == b || std::filesystem::equivalent(a, b, ec);
}

// The input a --keep names: the same file, or the same path as given, or a unique file name.
std::optional<std::size_t> kept_input(const std::vector<std::string>& inputs, const std::string& keep) {
  for (std::size_t i = 0; i < inputs.size(); ++i)
    if (same_file(inputs[i], keep)) return i;
  std::optional<std::size_t> by_name;
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    if (std::filesystem::path(inputs[i]).filename() != std::filesystem::path(keep).filename()) continue;
    if (by_name) return std::nullopt;
    by_name = i;
  }
  return by_name;
}

// Writes the proposed images and the reports; an error message, or nothing.
std::optional<std::string> write_outputs(const SeparateArgs& a, const study::SeparateResult& r,
                                         const std::vector<std::string>& outputs) {
  for (std::size_t i = 0; i < r.images.size(); ++i) {
    if (rest_requested()) return std::nullopt;
    SaveOptions options;
    options.new_file_mode = NewFileMode::of(a.inputs[i]);
    if (auto error = save_image_file(r.images[i].proposal, outputs[i], options)) return error;
  }
  const std::filesystem::path dir(a.out);
  const NewFileMode mode = NewFileMode::of_all({a.inputs.begin(), a.inputs.end()});
  if (auto e = write_file_atomically(dir / "separate.json", study::separate_json(r, outputs, a.model), mode)) return e;
  return write_file_atomically(dir / "separate.html", study::separate_html(r, outputs), mode);
}

void print_summary(const study::SeparateResult& r) {
  for (const study::SeparateImage& im : r.images) {
    std::printf("%s: identified %.0f %% -> %.0f %%, felt change %.1f JNDs%s\n", im.label.c_str(),
                100.0 * im.identified_before, 100.0 * im.identified_after, im.change_jnd, im.kept ? " (kept)" : "");
    for (const study::ParameterChange& c : im.changes) std::printf("  %s\n", c.text.c_str());
  }
  std::printf("information transfer %.2f -> %.2f bits; %d variants rendered\n", r.information_before_bits,
              r.information_after_bits, r.variants_rendered);
}

int run_separate_command(const SeparateArgs& a) {
  if (a.inputs.size() < 2) return usage_error(kProgram, "give at least two images");
  if (a.inputs.size() > kMaxCompareInputs)
    return usage_error(kProgram, std::to_string(a.inputs.size()) + " images (limit " + std::to_string(kMaxCompareInputs) + ")");
  if (!(a.target > 0.0 && a.target < 1.0)) return usage_error(kProgram, "--target must be in (0, 1), e.g. 0.9");
  study::SeparateRequest q;
  if (!a.vary.empty()) {
    const study::TactileParameterList list = study::parse_tactile_parameter_list(a.vary);
    if (!list.error.empty()) return usage_error(kProgram, "--vary: " + list.error);
    q.vary = list.set;
  }
  q.keep.assign(a.inputs.size(), false);
  for (const std::string& k : a.keep) {
    const auto i = kept_input(a.inputs, k);
    if (!i) return usage_error(kProgram, "--keep '" + k + "' is not one of the images");
    q.keep[*i] = true;
  }
  // The proposals go to DIR under the inputs' own names, never over an input.
  std::vector<std::string> outputs;
  std::map<std::string, std::string> names;
  for (const std::string& in : a.inputs) {
    const std::string name = std::filesystem::path(in).filename().string();
    if (names.count(name)) return usage_error(kProgram, "two images share the name '" + name + "' (" + names[name] + ", " + in + "): the proposals are written under the images' names");
    names[name] = in;
    const std::string out = (std::filesystem::path(a.out) / name).string();
    for (const std::string& other : a.inputs)
      if (same_file(out, other)) return usage_error(kProgram, "--out would write over the input '" + other + "'; choose another folder");
    outputs.push_back(out);
  }
  std::error_code ec;
  if (std::filesystem::exists(a.out, ec) && !std::filesystem::is_directory(a.out, ec)) {
    std::fprintf(stderr, "%s: error: --out must be a folder, and is a file\n", a.out.c_str());
    return kExitFailure;
  }

  for (const std::string& in : a.inputs) q.inputs.emplace_back(in);
  auto actuator = load_compare_actuator(a.actuator);
  if (!actuator) return kExitFailure;
  q.actuator = std::move(*actuator);
  std::shared_ptr<FeltAnalysis> felt;
  if (!a.actuator.empty()) {
    felt = load_felt_analysis(a.actuator);
    if (!felt) return kExitFailure;
    q.weak_primitives = [felt](const Image& image) { return weak_primitive_indices(image, *felt); };
    q.felt_band = felt->describe();
  }
  if (!a.model.empty()) {
    const auto model = load_model_argument(a.model, q.actuator);
    if (!model) return kExitFailure;
    q.discrimination = model->constants;
  }
  q.target = a.target;
  q.threads = a.threads;

  const SignalRestScope signals;
  q.should_stop = [] { return rest_requested(); };
  q.progress = [](const std::string& line) { std::fprintf(stderr, "%s: %s\n", kProgram, line.c_str()); };
  const study::SeparateResult r = study::run_separate(q);
  print_diagnostics(r.diagnostics);
  if (r.interrupted || rest_requested()) return interrupted();
  if (!r.ok()) return kExitFailure;
  if (r.already_distinct) {
    std::printf("every image is already predicted identified at least %.0f %% of the time (lowest %.0f %%): nothing to "
                "change, nothing written\n",
                100.0 * a.target, 100.0 * [&] {
                  double low = 1.0;
                  for (const auto& im : r.images) low = std::min(low, im.identified_before);
                  return low;
                }());
    return kExitOk;
  }
  std::filesystem::create_directories(a.out, ec);
  if (ec) {
    std::fprintf(stderr, "%s: error: cannot create the folder: %s\n", a.out.c_str(), ec.message().c_str());
    return kExitFailure;
  }
  if (const auto error = write_outputs(a, r, outputs)) {
    std::fprintf(stderr, "%s: %s\n", kProgram, error->c_str());
    return kExitFailure;
  }
  if (rest_requested()) return interrupted();
  print_summary(r);
  if (r.reached) {
    std::printf("target reached: every image identified at least %.0f %% of the time; written to %s\n", 100.0 * a.target,
                a.out.c_str());
    return kExitOk;
  }
  std::fprintf(stderr, "%s: the target of %.0f %% is out of reach; the best set found is written to %s\n", kProgram,
               100.0 * a.target, a.out.c_str());
  for (const std::string& l : r.limits) std::fprintf(stderr, "%s: limit: %s\n", kProgram, l.c_str());
  return kExitOutOfReach;
}

}  // namespace

void add_separate_command(CLI::App& vimg, int& exit_code) {
  CLI::App* sub = vimg.add_subcommand(
      "separate",
      "propose the smallest change of a set's tactile parameters (in JNDs felt) that lets people identify every image");
  sub->set_version_flag("--version", std::string(cmdline::version()), "print the version and exit");
  auto a = std::make_shared<SeparateArgs>();
  sub->add_option("IMAGE", a->inputs, "two or more .vimg or .png images of one canvas size")->required();
  sub->add_option("--actuator", a->actuator,
                  "actuator profile: a file, or a shipped profile's name (lra-175hz-drv2605l, erm-10mm, voice-coil-audio, "
                  "ideal); proposals stay in its felt band; default: ideal");
  sub->add_option("--out", a->out,
                  "folder for the proposed images (under their own names) and the report separate.json and separate.html; "
                  "created if missing")
      ->required();
  sub->add_option("--model", a->model, "MODEL.json of `vimg study fit` (default: the published figures' constants)");
  sub->add_option("--target", a->target, "share of trials every image is to be identified in, in (0, 1); default 0.9");
  sub->add_option("--vary", a->vary,
                  "the parameters it may change, comma separated: period, relief, pattern, gain, frequency, damping "
                  "(default: all)");
  sub->add_option("--keep", a->keep, "an image that stays as it is; repeat it for several");
  sub->add_option("--threads", a->threads, "threads that render (default: one per core)");
  sub->footer(
      "The set is predicted as `vimg compare` predicts it (the standard exploration, the actuator, the model). Exit "
      "status: 0 reached (or nothing to change), 3 the target is out of reach (the best set found is written and what "
      "limits it is printed), 1 bad input, 2 usage, 130/143 interrupted. docs/separate.md.");
  sub->callback([a, &exit_code] { exit_code = run_separate_command(*a); });
}

}  // namespace vimg::cli
