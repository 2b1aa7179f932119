#include "study/fit_model.hpp"

#include <cmath>
#include <cstdio>

#include "study/fit_nelder_mead.hpp"

namespace vimg::study {

namespace {

std::string number_text(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", v);
  return text;
}

// The likelihood of some participants' trials as a function of the free constants' coordinates.
struct Problem {
  const std::vector<CueMatrix>& cues;
  std::vector<ChoiceCounts> counts;
  const DiscriminationConstants& defaults;

  double nll(const std::vector<std::size_t>& free, std::span<const double> theta) const {
    return -log_likelihood(cues, counts, constants_at(defaults, free, theta));
  }
};

struct Optimum {
  std::vector<double> theta;
  double nll = 0.0;
};

std::vector<double> lower_edges(const std::vector<std::size_t>& free) {
  std::vector<double> v;
  for (const std::size_t k : free) v.push_back(theta_lower(k));
  return v;
}

std::vector<double> upper_edges(const std::vector<std::size_t>& free) {
  std::vector<double> v;
  for (const std::size_t k : free) v.push_back(theta_upper(k));
  return v;
}

Optimum fit(const Problem& p, const std::vector<std::size_t>& free, std::vector<double> start) {
  const NelderMeadResult r = minimise_nelder_mead([&](std::span<const double> theta) { return p.nll(free, theta); },
                                                  std::move(start), lower_edges(free), upper_edges(free));
  return {r.x, r.value};
}

std::vector<double> default_start(const std::vector<std::size_t>& free, const DiscriminationConstants& defaults) {
  std::vector<double> theta;
  for (const std::size_t k : free) theta.push_back(to_theta(k, constant_value(defaults, k), defaults));
  return theta;
}

// The profile: the smallest -ln L with coordinate m held at x, the others re-fitted from `hat`.
double profile(const Problem& p, const std::vector<std::size_t>& free, std::size_t m, double x, const std::vector<double>& hat) {
  std::vector<std::size_t> others;
  std::vector<double> start;
  for (std::size_t q = 0; q < free.size(); ++q) {
    if (q == m) continue;
    others.push_back(free[q]);
    start.push_back(hat[q]);
  }
  const auto full = [&](std::span<const double> rest) {
    std::vector<double> theta;
    for (std::size_t q = 0, r = 0; q < free.size(); ++q) theta.push_back(q == m ? x : rest[r++]);
    return theta;
  };
  if (others.empty()) return p.nll(free, full({}));
  const NelderMeadResult r = minimise_nelder_mead([&](std::span<const double> rest) { return p.nll(free, full(rest)); },
                                                  std::move(start), lower_edges(others), upper_edges(others));
  return r.value;
}

struct Side {
  double theta = 0.0;
  bool at_edge = false;
};

// Where the profile of coordinate m rises kProfileDrop95 above the optimum, towards `edge`.
Side profile_side(const Problem& p, const std::vector<std::size_t>& free, std::size_t m, const Optimum& best, double edge) {
  const double target = best.nll + kProfileDrop95;
  if (std::abs(edge - best.theta[m]) < 1e-9 || profile(p, free, m, edge, best.theta) <= target) return {edge, true};
  double inside = best.theta[m], outside = edge;
  for (int step = 0; step < 18; ++step) {
    const double mid = 0.5 * (inside + outside);
    (profile(p, free, m, mid, best.theta) <= target ? inside : outside) = mid;
  }
  return {0.5 * (inside + outside), false};
}

// The lapse rate always; a cue's weight when some pair of a set with trials lies apart in it.
std::vector<std::size_t> candidate_constants(const FitData& data, const std::vector<ChoiceCounts>& pooled,
                                             std::vector<std::string>& warnings) {
  std::vector<CueMatrix> tried;
  for (std::size_t s = 0; s < data.set_cues.size(); ++s) {
    if (set_trials(pooled[s]) > 0.0) tried.push_back(data.set_cues[s]);
  }
  std::vector<std::size_t> free{0};
  for (std::size_t c = 0; c < kCueCount; ++c) {
    if (cue_separates_any_pair(tried, c)) {
      free.push_back(1 + c);
    } else {
      warnings.push_back(fit_constant_name(1 + c) + ": no pair of images of the sets with trials differs in the cue '" +
                         std::string(cue_name(c)) + "'; it keeps its default");
    }
  }
  return free;
}

std::string edge_text(std::size_t k, const DiscriminationConstants& defaults) {
  return k == 0 ? "a lapse rate of " + number_text(kMaxFittedLapse)
                : number_text(from_theta(k, theta_upper(k), defaults)) + " (1000 times its default)";
}

}  // namespace

std::optional<std::string> fit_refusal(const FitData& data) {
  const std::vector<ChoiceCounts> pooled = pooled_counts(data);
  const double trials = total_trials(pooled);
  if (trials == 0.0) return "the trial files hold no trials of the study's sets: nothing to fit";
  std::size_t with_trials = 0;
  for (std::size_t p = 0; p < data.counts.size(); ++p) with_trials += total_trials(data.counts[p]) > 0.0;
  if (with_trials < 2) {
    return "the trials are of one participant only (" + (data.participants.empty() ? std::string() : data.participants[0]) +
           "): the fit is judged by leaving one participant out, which needs at least two";
  }
  std::vector<std::string> unused;
  const double free = static_cast<double>(candidate_constants(data, pooled, unused).size());
  if (trials < kMinTrialsPerFreeConstant * free) {
    return number_text(trials) + " trials for " + number_text(free) + " free constants: at least " +
           number_text(kMinTrialsPerFreeConstant) + " trials per constant (" + number_text(kMinTrialsPerFreeConstant * free) +
           ") are needed";
  }
  return std::nullopt;
}

ModelFit fit_discrimination_model(const FitData& data, const FitOptions& options) {
  const DiscriminationConstants& defaults = options.defaults;
  const auto say = [&](const std::string& line) {
    if (options.progress) options.progress(line);
  };
  ModelFit r;
  r.defaults = r.constants = defaults;
  const Problem all{data.set_cues, pooled_counts(data), defaults};
  r.trials = total_trials(all.counts);
  std::vector<std::size_t> free = candidate_constants(data, all.counts, r.warnings);

  Optimum best;
  std::vector<Side> lower, upper;
  for (;;) {
    say("fitting " + std::to_string(free.size()) + " constants on " + number_text(r.trials) + " trials");
    best = fit(all, free, default_start(free, defaults));
    lower.assign(free.size(), {});
    upper.assign(free.size(), {});
    std::vector<std::size_t> kept;
    for (std::size_t m = 0; m < free.size(); ++m) {
      say("profile interval of " + fit_constant_name(free[m]) + " (" + std::to_string(m + 1) + " of " +
          std::to_string(free.size()) + ")");
      upper[m] = profile_side(all, free, m, best, theta_upper(free[m]));
      if (upper[m].at_edge) {
        r.warnings.push_back(fit_constant_name(free[m]) + ": the likelihood stays within " + number_text(kProfileDrop95) +
                             " of its maximum up to " + edge_text(free[m], defaults) +
                             ", so the trials cannot identify it; it keeps its default " +
                             number_text(constant_value(defaults, free[m])));
        continue;
      }
      lower[m] = profile_side(all, free, m, best, theta_lower(free[m]));
      kept.push_back(free[m]);
    }
    if (kept.size() == free.size()) break;
    free = kept;
  }
  r.constants = constants_at(defaults, free, best.theta);

  r.report.push_back({"temperature_jnd", defaults.temperature_jnd, defaults.temperature_jnd, false, 0.0, 0.0, false});
  for (std::size_t k = 0; k < kFitConstantCount; ++k) {
    ConstantFit c{fit_constant_name(k), constant_value(r.constants, k), constant_value(defaults, k), false, 0.0, 0.0, false};
    for (std::size_t m = 0; m < free.size(); ++m) {
      if (free[m] != k) continue;
      c.fitted = true;
      c.lower_at_edge = lower[m].at_edge;
      c.lower = c.lower_at_edge ? 0.0 : from_theta(k, lower[m].theta, defaults);
      c.upper = from_theta(k, upper[m].theta, defaults);
    }
    r.report.push_back(c);
  }
  r.ll_fitted = log_likelihood(data.set_cues, all.counts, r.constants);
  r.ll_default = log_likelihood(data.set_cues, all.counts, defaults);
  r.ll_chance = chance_log_likelihood(all.counts);

  for (std::size_t p = 0; p < data.participants.size(); ++p) {
    say("leaving out participant " + data.participants[p] + " (" + std::to_string(p + 1) + " of " +
        std::to_string(data.participants.size()) + ")");
    const Problem others{data.set_cues, pooled_counts(data, p), defaults};
    const Optimum fitted = fit(others, free, best.theta);
    HeldOutParticipant h;
    h.participant = data.participants[p];
    h.trials = total_trials(data.counts[p]);
    h.ll_fitted = log_likelihood(data.set_cues, data.counts[p], constants_at(defaults, free, fitted.theta));
    h.ll_default = log_likelihood(data.set_cues, data.counts[p], defaults);
    h.ll_chance = chance_log_likelihood(data.counts[p]);
    r.held_out_ll_fitted += h.ll_fitted;
    r.held_out_ll_default += h.ll_default;
    r.held_out_ll_chance += h.ll_chance;
    r.held_out.push_back(h);
  }
  return r;
}

}  // namespace vimg::study
