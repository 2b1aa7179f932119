// `vimg study fit TRIALS... --study STUDY.xml [--actuator P] --out MODEL.json`: the discrimination
// model's constants fitted by maximum likelihood on the matching test's trials, with 95 % profile
// intervals and the leave-one-participant-out ln-likelihood against the default constants
// (docs/studies.md, "Fitting the model"; study/fit_study.hpp reads, study/fit_model.hpp fits).
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "cli/command.hpp"
#include "cli/compare_inputs.hpp"
#include "storage/atomic_file.hpp"
#include "storage/file_extension.hpp"
#include "storage/print_diagnostics.hpp"
#include "storage/study/perception_model_file.hpp"
#include "study/fit_study.hpp"

namespace vimg::cli {

namespace {

constexpr const char* kProgram = "vimg study fit";

struct FitArgs {
  std::vector<std::string> trials;
  std::string study;
  std::string actuator;
  std::string out;
};

void progress(const std::string& line) { std::fprintf(stderr, "%s: %s\n", kProgram, line.c_str()); }

std::string interval_text(const study::ConstantFit& c) {
  char text[96];
  if (!c.fitted) return c.name == "temperature_jnd" ? "fixed (the weights carry the scale)" : "kept its default (see the warnings)";
  std::snprintf(text, sizeof text, "[%.4g, %.4g]%s", c.lower, c.upper, c.lower_at_edge ? " (at most)" : "");
  return text;
}

void print_fit(const study::ModelFit& fit, const study::FitData& data, std::size_t sets, const std::string& actuator) {
  std::printf("%s: %.0f trials of %zu participants in %zu set%s, through the actuator %s\n", kProgram, fit.trials,
              data.participants.size(), sets, sets == 1 ? "" : "s", actuator.c_str());
  std::printf("\n%-22s %10s %10s  %s\n", "constant", "default", "fitted", "95 % interval (profile likelihood)");
  for (const study::ConstantFit& c : fit.report) {
    std::printf("%-22s %10.4g %10.4g  %s\n", c.name.c_str(), c.default_value, c.value, interval_text(c).c_str());
  }
  std::printf("\nln-likelihood of all trials: fitted %.2f, default %.2f, guessing %.2f\n", fit.ll_fitted, fit.ll_default,
              fit.ll_chance);
  std::printf("\nLeave one participant out: each participant's trials under the constants fitted on the others\n");
  std::printf("%-16s %8s %12s %12s %12s\n", "participant", "trials", "fitted", "default", "guessing");
  for (const study::HeldOutParticipant& h : fit.held_out) {
    std::printf("%-16s %8.0f %12.2f %12.2f %12.2f\n", h.participant.c_str(), h.trials, h.ll_fitted, h.ll_default, h.ll_chance);
  }
  std::printf("%-16s %8.0f %12.2f %12.2f %12.2f\n", "total", fit.trials, fit.held_out_ll_fitted, fit.held_out_ll_default,
              fit.held_out_ll_chance);
  const double gain = fit.held_out_ll_fitted - fit.held_out_ll_default;
  std::printf("held out, the fitted constants %s the defaults by %.2f (ln-likelihood per trial %+.4f)\n",
              gain >= 0.0 ? "beat" : "fall behind", std::abs(gain), gain / fit.trials);
}

int run_fit(const FitArgs& a) {
  if (lower_extension(a.out) != ".json") return usage_error(kProgram, "--out must end in .json: '" + a.out + "'");
  for (const std::string& input : a.trials) {
    std::error_code ec;
    if (input == a.out || std::filesystem::equivalent(input, a.out, ec))
      return usage_error(kProgram, "--out names an input file: '" + a.out + "'");
  }
  const auto actuator = load_compare_actuator(a.actuator);
  if (!actuator) return kExitFailure;

  study::StudyFitRequest request;
  request.study = a.study;
  request.trial_files.assign(a.trials.begin(), a.trials.end());
  request.actuator = *actuator;
  request.progress = progress;
  const study::StudyFitInputs inputs = study::read_study_fit_inputs(request);
  print_diagnostics(inputs.diagnostics);
  if (!inputs.ok()) {
    std::fprintf(stderr, "%s: %s not written\n", kProgram, a.out.c_str());
    return kExitFailure;
  }
  if (const auto refusal = study::fit_refusal(inputs.data)) {
    std::fprintf(stderr, "%s: error: %s; %s not written\n", kProgram, refusal->c_str(), a.out.c_str());
    return kExitFailure;
  }
  study::FitOptions options;
  options.defaults = request.defaults;
  options.progress = progress;
  const study::ModelFit fit = study::fit_discrimination_model(inputs.data, options);
  for (const std::string& w : fit.warnings) std::fprintf(stderr, "%s: warning: %s\n", kProgram, w.c_str());
  print_fit(fit, inputs.data, inputs.sets_with_trials, actuator->name);

  std::vector<std::filesystem::path> sources(a.trials.begin(), a.trials.end());
  const std::string text = perception_model_json(study::perception_model_of(fit, request, inputs.data));
  if (const auto error = write_file_atomically(a.out, text, NewFileMode::of_all(sources))) {
    std::fprintf(stderr, "%s: %s\n", kProgram, error->c_str());
    return kExitFailure;
  }
  return kExitOk;
}

}  // namespace

void add_study_fit(CLI::App& study, int& exit_code) {
  CLI::App* fit = study.add_subcommand(
      "fit", "fit the discrimination model's constants on the matching test's trials (maximum likelihood; docs/studies.md)");
  fit->set_version_flag("--version", std::string(cmdline::version()), "print the version and exit");
  auto a = std::make_shared<FitArgs>();
  fit->add_option("TRIALS", a->trials, "the matching test's trial files (CSV, one per participant) of the study")->required();
  fit->add_option("--study", a->study, "the matching study file (XML) the trials were run with: its sets and images")
      ->required();
  fit->add_option("--actuator", a->actuator,
                  "the actuator the participants felt the images through: a profile file or a shipped profile's name, as "
                  "for vimg compare; default: ideal");
  fit->add_option("--out", a->out, "MODEL.json for vimg compare --model, written atomically")->required();
  fit->footer(
      "Each set's images are rendered as vimg compare renders them. Free: the lapse rate and each cue's weight (the "
      "temperature stays at its default: only weight / temperature enters the model). 95 % profile-likelihood intervals; a "
      "constant the trials cannot identify keeps its default with a warning. Leave-one-participant-out ln-likelihood against "
      "the default constants. Refused (exit 1, nothing written): a trial of another study, no trials, one participant, fewer "
      "than 10 trials per free constant.");
  fit->callback([a, &exit_code] { exit_code = run_fit(*a); });
}

}  // namespace vimg::cli
