#include "study/fit_model.hpp"

#include <cmath>
#include <cstdio>
#include <limits>

namespace vimg::study {

namespace {

std::string number_text(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", v);
  return text;
}

// The value of constant k at coordinate theta; an open upper end of a weight is unbounded.
double end_value(std::size_t k, double theta, bool open_upper, const DiscriminationConstants& defaults) {
  if (open_upper && k != 0) return std::numeric_limits<double>::infinity();
  return from_theta(k, theta, defaults);
}

// The defaults with the lapse rate fitted on `p`'s trials: the baseline a fit must beat.
DiscriminationConstants baseline_of(const FitProblem& p) {
  const std::vector<std::size_t> lapse{0};
  const Optimum o = fit_constants(p, lapse, default_start(lapse, p.defaults));
  return constants_at(p.defaults, lapse, o.theta);
}

std::vector<ConstantFit> report_of(const FittedChoice& chosen, const BootstrapIntervals& boot,
                                   const DiscriminationConstants& defaults) {
  std::vector<ConstantFit> report;
  ConstantFit temperature;
  temperature.name = "temperature_jnd";
  temperature.value = temperature.default_value = defaults.temperature_jnd;
  report.push_back(temperature);
  for (std::size_t k = 0; k < kFitConstantCount; ++k) {
    ConstantFit c;
    c.name = fit_constant_name(k);
    c.value = constant_value(chosen.constants, k);
    c.default_value = constant_value(defaults, k);
    for (std::size_t m = 0; m < chosen.free.size(); ++m) {
      if (chosen.free[m] != k) continue;
      c.fitted = true;
      c.at_least = chosen.at_least[m];
      c.lower_open = boot.lower[m].at_edge || chosen.lower[m].at_edge;
      c.upper_open = boot.upper[m].at_edge || chosen.upper[m].at_edge;
      c.lower = c.lower_open ? 0.0 : from_theta(k, boot.lower[m].theta, defaults);
      c.upper = end_value(k, c.upper_open ? theta_upper(k) : boot.upper[m].theta, c.upper_open, defaults);
      c.profile_lower = chosen.lower[m].at_edge ? 0.0 : from_theta(k, chosen.lower[m].theta, defaults);
      c.profile_upper = end_value(k, chosen.upper[m].theta, chosen.upper[m].at_edge, defaults);
    }
    report.push_back(c);
  }
  return report;
}

}  // namespace

std::optional<std::string> fit_refusal(const FitData& data) {
  const FitProblem all{&data.set_cues, pooled_counts(data), {}};
  const double trials = total_trials(all.counts);
  if (trials == 0.0) return "the trial files hold no trials of the study's sets: nothing to fit";
  std::size_t with_trials = 0;
  for (std::size_t p = 0; p < data.counts.size(); ++p) with_trials += total_trials(data.counts[p]) > 0.0;
  if (with_trials < 2) {
    return "the trials are of one participant only (" + (data.participants.empty() ? std::string() : data.participants[0]) +
           "): the fit is judged by leaving one participant out, which needs at least two";
  }
  std::vector<std::string> unused;
  const double free = static_cast<double>(candidate_constants(all, unused).size());
  if (trials < kMinTrialsPerFreeConstant * free) {
    return number_text(trials) + " trials for " + number_text(free) + " free constants: at least " +
           number_text(kMinTrialsPerFreeConstant) + " trials per constant (" + number_text(kMinTrialsPerFreeConstant * free) +
           ") are needed";
  }
  return std::nullopt;
}

ModelFit fit_identification_model(const FitData& data, const FitOptions& options) {
  const DiscriminationConstants& defaults = options.defaults;
  const auto say = [&](const std::string& line) {
    if (options.progress) options.progress(line);
  };
  ModelFit r;
  r.defaults = defaults;
  const FitProblem all{&data.set_cues, pooled_counts(data), defaults};
  r.trials = total_trials(all.counts);
  const FittedChoice chosen = choose_and_fit(all, options.progress);
  r.constants = chosen.constants;
  r.warnings = chosen.warnings;

  BootstrapOptions boot_options = options.bootstrap;
  if (!boot_options.progress) boot_options.progress = options.progress;
  const BootstrapIntervals boot = bootstrap_over_participants(data, chosen.free, chosen.best.theta, defaults, boot_options);
  r.bootstrap_replicates = boot_options.replicates;
  r.report = report_of(chosen, boot, defaults);
  if (data.participants.size() < kBootstrapCheckedParticipants) {
    r.warnings.push_back("the intervals resample " + std::to_string(data.participants.size()) +
                         " participants; their coverage is checked from " + std::to_string(kBootstrapCheckedParticipants) +
                         " (tests/study_fit/fit_coverage_test.cpp), and with fewer they are likely too narrow");
  }

  r.baseline = baseline_of(all);
  r.ll_fitted = log_likelihood(data.set_cues, all.counts, r.constants);
  r.ll_baseline = log_likelihood(data.set_cues, all.counts, r.baseline);
  r.ll_default = log_likelihood(data.set_cues, all.counts, defaults);
  r.ll_chance = chance_log_likelihood(all.counts);

  for (std::size_t p = 0; p < data.participants.size(); ++p) {
    say("leaving out participant " + data.participants[p] + " (" + std::to_string(p + 1) + " of " +
        std::to_string(data.participants.size()) + "): choosing and fitting on the others");
    const FitProblem others{&data.set_cues, pooled_counts(data, p), defaults};
    HeldOutParticipant h;
    h.participant = data.participants[p];
    h.trials = total_trials(data.counts[p]);
    h.constants = choose_and_fit(others, nullptr).constants;
    h.ll_fitted = log_likelihood(data.set_cues, data.counts[p], h.constants);
    h.ll_baseline = log_likelihood(data.set_cues, data.counts[p], baseline_of(others));
    h.ll_default = log_likelihood(data.set_cues, data.counts[p], defaults);
    h.ll_chance = chance_log_likelihood(data.counts[p]);
    r.held_out_ll_fitted += h.ll_fitted;
    r.held_out_ll_baseline += h.ll_baseline;
    r.held_out_ll_default += h.ll_default;
    r.held_out_ll_chance += h.ll_chance;
    r.held_out.push_back(h);
  }
  return r;
}

}  // namespace vimg::study
