// `vimg study fit TRIALS... --study STUDY.xml [--actuator P] --out MODEL.json`: the identification
// model's constants fitted by maximum likelihood on the matching test's trials, with 95 % intervals
// by a bootstrap over participants (and the pooled trials' profile intervals) and the
// leave-one-participant-out ln-likelihood against the defaults with a fitted lapse rate
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

std::string range_text(double lower, double upper, bool lower_open) {
  char text[96];
  if (std::isinf(upper)) {
    std::snprintf(text, sizeof text, "at least %.4g", lower);
  } else if (lower_open) {
    std::snprintf(text, sizeof text, "at most %.4g", upper);
  } else {
    std::snprintf(text, sizeof text, "[%.4g, %.4g]", lower, upper);
  }
  return text;
}

std::string interval_text(const study::ConstantFit& c) {
  if (!c.fitted) return c.name == "temperature_jnd" ? "fixed (the weights carry the scale)" : "kept its default (see the warnings)";
  return range_text(c.lower, c.upper, c.lower_open);
}

std::string profile_text(const study::ConstantFit& c) {
  if (!c.fitted) return "";
  return range_text(c.profile_lower, c.profile_upper, c.profile_lower == 0.0);
}

void print_fit(const study::ModelFit& fit, const study::FitData& data, std::size_t sets, const std::string& actuator) {
  std::printf("%s: %.0f trials of %zu participants in %zu set%s, through the actuator %s\n", kProgram, fit.trials,
              data.participants.size(), sets, sets == 1 ? "" : "s", actuator.c_str());
  std::printf("\n%-22s %10s %10s  %-28s %s\n", "constant", "default", "fitted", "95 % (bootstrap, participants)",
              "95 % (profile, pooled trials)");
  for (const study::ConstantFit& c : fit.report) {
    std::printf("%-22s %10.4g %10.4g  %-28s %s\n", c.name.c_str(), c.default_value, c.value, interval_text(c).c_str(),
                profile_text(c).c_str());
  }
  std::printf("(%zu bootstrap resamples of the participants)\n", fit.bootstrap_replicates);
  std::printf("\nln-likelihood of all trials: fitted %.2f, baseline (the defaults, lapse rate fitted: %.4g) %.2f, "
              "defaults %.2f, guessing %.2f\n",
              fit.ll_fitted, fit.baseline.lapse_rate, fit.ll_baseline, fit.ll_default, fit.ll_chance);
  std::printf("\nLeave one participant out: each participant's trials under what was chosen and fitted on the others\n");
  std::printf("%-16s %8s %12s %12s %12s %12s\n", "participant", "trials", "fitted", "baseline", "defaults", "guessing");
  for (const study::HeldOutParticipant& h : fit.held_out) {
    std::printf("%-16s %8.0f %12.2f %12.2f %12.2f %12.2f\n", h.participant.c_str(), h.trials, h.ll_fitted, h.ll_baseline,
                h.ll_default, h.ll_chance);
  }
  std::printf("%-16s %8.0f %12.2f %12.2f %12.2f %12.2f\n", "total", fit.trials, fit.held_out_ll_fitted, fit.held_out_ll_baseline,
              fit.held_out_ll_default, fit.held_out_ll_chance);
  const double gain = fit.held_out_ll_fitted - fit.held_out_ll_baseline;
  std::printf("held out, the fitted constants %s the baseline (the defaults with a fitted lapse rate) by %.2f "
              "(ln-likelihood per trial %+.4f)\n",
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
  const study::ModelFit fit = study::fit_identification_model(inputs.data, options);
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
      "fit", "fit the identification model's constants on the matching test's trials (maximum likelihood; docs/studies.md)");
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
      "temperature belongs to two-interval discrimination and stays at its default). 95 % intervals by a bootstrap over "
      "participants (1000 resamples), beside the profile-likelihood intervals of the pooled trials; a weight the trials bound "
      "from below only is 'at least' its bound and held at its default, or at the bound when they reject the default; a "
      "constant the trials say nothing about keeps its default with a warning. Leave one participant out, everything chosen "
      "and fitted on the others, against the defaults with a fitted lapse rate. Refused (exit 1, nothing written): a trial of "
      "another study, no trials, one participant, fewer than 10 trials per free constant.");
  fit->callback([a, &exit_code] { exit_code = run_fit(*a); });
}

}  // namespace vimg::cli
