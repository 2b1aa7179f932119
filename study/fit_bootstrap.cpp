#include "study/fit_bootstrap.hpp"

#include <algorithm>
#include <cmath>

#include <boost/math/distributions/normal.hpp>
#include <boost/math/distributions/students_t.hpp>

#include "primitives/random/splitmix64.hpp"
#include "storage/parallel_tasks.hpp"
#include "study/fit_search.hpp"

namespace vimg::study {

double expanded_tail(double confidence, std::size_t participants) {
  const double alpha = 1.0 - confidence;
  if (participants < 2) return 0.5 * alpha;
  const double n = static_cast<double>(participants);
  const double t = boost::math::quantile(boost::math::students_t(n - 1.0), 1.0 - 0.5 * alpha);
  return boost::math::cdf(boost::math::normal(), -std::sqrt(n / (n - 1.0)) * t);
}

double quantile_type7(std::vector<double>& values, double q) {
  std::sort(values.begin(), values.end());
  if (values.empty()) return NAN;
  const double h = (static_cast<double>(values.size()) - 1.0) * std::clamp(q, 0.0, 1.0);
  const auto below = static_cast<std::size_t>(std::floor(h));
  const std::size_t above = std::min(below + 1, values.size() - 1);
  return values[below] + (h - static_cast<double>(below)) * (values[above] - values[below]);
}

BootstrapIntervals bootstrap_over_participants(const FitData& data, const std::vector<std::size_t>& free,
                                               const std::vector<double>& start, const DiscriminationConstants& defaults,
                                               const BootstrapOptions& options) {
  const std::size_t n = data.counts.size();
  NelderMeadOptions search;
  search.tolerance = kBootstrapTolerance;
  // fits[b][m]: replicate b's value of constant m; each replicate draws from its own generator, so
  // the replicates are the same however many threads fit them.
  std::vector<std::vector<double>> fits(options.replicates);
  const int threads = worker_thread_count(options.threads);
  for (std::size_t done = 0; done < options.replicates; done += kBootstrapChunk) {
    if (options.progress)
      options.progress("bootstrap over participants: replicates " + std::to_string(done + 1) + " to " +
                       std::to_string(std::min(done + kBootstrapChunk, options.replicates)) + " of " +
                       std::to_string(options.replicates));
    run_tasks(std::min(kBootstrapChunk, options.replicates - done), threads, [&](std::size_t i, int) {
      const std::size_t b = done + i;
      SplitMix64 random(mix64(options.seed + (b + 1) * kSplitMixGolden));
      std::vector<std::size_t> drawn(n);
      for (std::size_t& p : drawn) p = static_cast<std::size_t>(random.below(n));
      const FitProblem resample{&data.set_cues, pooled_counts_of(data, drawn), defaults};
      fits[b] = fit_constants(resample, free, start, search).theta;
    });
  }
  const double tail = expanded_tail(options.confidence, n);
  BootstrapIntervals r;
  for (std::size_t m = 0; m < free.size(); ++m) {
    std::vector<double> values;
    for (const std::vector<double>& fit : fits) values.push_back(fit[m]);
    const double lo = quantile_type7(values, tail), hi = quantile_type7(values, 1.0 - tail);
    r.lower.push_back({lo, lo <= theta_lower(free[m]) + 1e-3});
    r.upper.push_back({hi, hi >= theta_upper(free[m]) - 1e-3});
  }
  return r;
}

}  // namespace vimg::study
