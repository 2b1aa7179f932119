#include "study/fit_search.hpp"

#include <algorithm>
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

std::string edge_text(std::size_t k, const DiscriminationConstants& defaults) {
  return k == 0 ? "a lapse rate of " + number_text(kMaxFittedLapse)
                : number_text(from_theta(k, theta_upper(k), defaults)) + " (1000 times its default)";
}

// Fits `p` with the at-least weights of `c` held (at their default, or at their profile's lower
// end when the trials reject the default) and the other identified constants free.
void hold_lower_bounds(const FitProblem& p, FittedChoice& c) {
  if (std::find(c.at_least.begin(), c.at_least.end(), true) == c.at_least.end()) {
    c.constants = constants_at(p.defaults, c.free, c.best.theta);
    return;
  }
  FitProblem held = p;
  std::vector<std::size_t> rest;
  std::vector<double> start;
  for (std::size_t m = 0; m < c.free.size(); ++m) {
    const std::size_t k = c.free[m];
    if (!c.at_least[m]) {
      rest.push_back(k);
      start.push_back(c.best.theta[m]);
      continue;
    }
    const double bound = from_theta(k, c.lower[m].theta, p.defaults);
    const double default_value = constant_value(p.defaults, k);
    const bool allowed = default_value >= bound;
    set_constant_value(held.defaults, k, allowed ? default_value : bound);
    c.warnings.push_back(fit_constant_name(k) + ": the likelihood stays within " + number_text(kProfileDrop95) +
                         " of its maximum up to " + edge_text(k, p.defaults) + ", so the trials bound it from below only (at least " +
                         number_text(bound) + "); it is held at " +
                         (allowed ? "its default " + number_text(default_value) + ", which they allow"
                                  : number_text(bound) + ", its default " + number_text(default_value) + " being below what they allow"));
  }
  const Optimum fitted = fit_constants(held, rest, start);
  c.constants = constants_at(held.defaults, rest, fitted.theta);
}

}  // namespace

std::vector<double> default_start(const std::vector<std::size_t>& free, const DiscriminationConstants& defaults) {
  std::vector<double> theta;
  for (const std::size_t k : free) theta.push_back(to_theta(k, constant_value(defaults, k), defaults));
  return theta;
}

Optimum fit_constants(const FitProblem& p, const std::vector<std::size_t>& free, std::vector<double> start,
                      const NelderMeadOptions& options) {
  const NelderMeadResult r = minimise_nelder_mead([&](std::span<const double> theta) { return p.nll(free, theta); },
                                                  std::move(start), lower_edges(free), upper_edges(free), options);
  return {r.x, r.value};
}

double profile_nll(const FitProblem& p, const std::vector<std::size_t>& free, std::size_t m, double x,
                   const std::vector<double>& hat) {
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

ProfileSide profile_side(const FitProblem& p, const std::vector<std::size_t>& free, std::size_t m, const Optimum& best,
                         double edge) {
  const double target = best.nll + kProfileDrop95;
  if (std::abs(edge - best.theta[m]) < 1e-9 || profile_nll(p, free, m, edge, best.theta) <= target) return {edge, true};
  double inside = best.theta[m], outside = edge;
  for (int step = 0; step < 18; ++step) {
    const double mid = 0.5 * (inside + outside);
    (profile_nll(p, free, m, mid, best.theta) <= target ? inside : outside) = mid;
  }
  return {0.5 * (inside + outside), false};
}

std::vector<std::size_t> candidate_constants(const FitProblem& p, std::vector<std::string>& warnings) {
  std::vector<CueMatrix> tried;
  for (std::size_t s = 0; s < p.cues->size(); ++s) {
    if (set_trials(p.counts[s]) > 0.0) tried.push_back((*p.cues)[s]);
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

FittedChoice choose_and_fit(const FitProblem& p, void (*say)(const std::string& line)) {
  const auto progress = [&](const std::string& line) {
    if (say) say(line);
  };
  FittedChoice c;
  c.free = candidate_constants(p, c.warnings);
  const double trials = total_trials(p.counts);
  for (;;) {
    progress("fitting " + std::to_string(c.free.size()) + " constants on " + number_text(trials) + " trials");
    c.best = fit_constants(p, c.free, default_start(c.free, p.defaults));
    c.lower.assign(c.free.size(), {});
    c.upper.assign(c.free.size(), {});
    std::vector<std::size_t> kept;
    for (std::size_t m = 0; m < c.free.size(); ++m) {
      const std::size_t k = c.free[m];
      progress("profile interval of " + fit_constant_name(k) + " (" + std::to_string(m + 1) + " of " +
               std::to_string(c.free.size()) + ")");
      c.upper[m] = profile_side(p, c.free, m, c.best, theta_upper(k));
      c.lower[m] = profile_side(p, c.free, m, c.best, theta_lower(k));
      if (c.upper[m].at_edge && c.lower[m].at_edge) {
        c.warnings.push_back(fit_constant_name(k) + ": the likelihood stays within " + number_text(kProfileDrop95) +
                             " of its maximum from 0 up to " + edge_text(k, p.defaults) +
                             ", so the trials say nothing about it; it keeps its default " +
                             number_text(constant_value(p.defaults, k)));
        continue;
      }
      kept.push_back(k);
    }
    if (kept.size() == c.free.size()) break;
    c.free = kept;
  }
  c.at_least.assign(c.free.size(), false);
  for (std::size_t m = 0; m < c.free.size(); ++m) c.at_least[m] = c.free[m] != 0 && c.upper[m].at_edge;
  hold_lower_bounds(p, c);
  return c;
}

}  // namespace vimg::study
