#include "study/statistics.hpp"

#include <boost/math/distributions/normal.hpp>
#include <boost/math/distributions/students_t.hpp>
#include <algorithm>
#include <cmath>

namespace vimg::study {

namespace {

// Sum of squared deviations from the mean (two passes: no cancellation for data far from zero).
double squared_deviations(std::span<const double> values, double mean) {
  double sum = 0.0;
  for (const double x : values) sum += (x - mean) * (x - mean);
  return sum;
}

double mean_of(std::span<const double> values) {
  double sum = 0.0;
  for (const double x : values) sum += x;
  return values.empty() ? 0.0 : sum / static_cast<double>(values.size());
}

double sample_variance(std::span<const double> values) {
  return squared_deviations(values, mean_of(values)) / static_cast<double>(values.size() - 1);
}

bool valid_level(double level) { return level > 0.0 && level < 1.0; }

}  // namespace

Summary summarize(std::span<const double> values) {
  Summary s;
  s.n = values.size();
  s.mean = mean_of(values);
  if (s.n >= 2) s.sd = std::sqrt(sample_variance(values));
  return s;
}

std::optional<Interval> wilson_interval(std::size_t successes, std::size_t trials, double level) {
  if (trials == 0 || successes > trials || !valid_level(level)) return std::nullopt;
  const boost::math::normal_distribution<double> normal;
  const double z = boost::math::quantile(normal, (1.0 + level) / 2.0);
  const double n = static_cast<double>(trials);
  const double p = static_cast<double>(successes) / n;
  const double z2 = z * z;
  const double denominator = 1.0 + z2 / n;
  const double centre = (p + z2 / (2.0 * n)) / denominator;
  const double half = z / denominator * std::sqrt(p * (1.0 - p) / n + z2 / (4.0 * n * n));
  // At p = 0 (1) the lower (upper) bound is exactly 0 (1), where rounding would leave a hair beside it;
  // elsewhere the bounds keep p between them.
  const double lower = successes == 0 ? 0.0 : std::min(p, centre - half);
  const double upper = successes == trials ? 1.0 : std::max(p, centre + half);
  return Interval{std::max(0.0, lower), std::min(1.0, upper)};
}

std::optional<Interval> t_interval_of_mean(double mean, double sd, std::size_t n, double level) {
  if (n < 2 || !std::isfinite(mean) || !std::isfinite(sd) || sd < 0.0 || !valid_level(level)) return std::nullopt;
  const boost::math::students_t_distribution<double> t(static_cast<double>(n - 1));
  const double half = boost::math::quantile(t, (1.0 + level) / 2.0) * sd / std::sqrt(static_cast<double>(n));
  return Interval{mean - half, mean + half};
}

std::optional<Interval> t_interval_of_mean(std::span<const double> values, double level) {
  const Summary s = summarize(values);
  if (!s.sd) return std::nullopt;
  return t_interval_of_mean(s.mean, *s.sd, s.n, level);
}

std::optional<WelchTest> welch_t_test(std::span<const double> a, std::span<const double> b) {
  if (a.size() < 2 || b.size() < 2) return std::nullopt;
  const double na = static_cast<double>(a.size());
  const double nb = static_cast<double>(b.size());
  const double qa = sample_variance(a) / na;  // squared standard errors
  const double qb = sample_variance(b) / nb;
  const double se2 = qa + qb;
  if (!(se2 > 0.0) || !std::isfinite(se2)) return std::nullopt;
  WelchTest w;
  w.t = (mean_of(a) - mean_of(b)) / std::sqrt(se2);
  w.df = se2 * se2 / (qa * qa / (na - 1.0) + qb * qb / (nb - 1.0));
  if (!std::isfinite(w.t) || !std::isfinite(w.df) || !(w.df > 0.0)) return std::nullopt;
  const boost::math::students_t_distribution<double> t(w.df);
  w.p = std::min(1.0, 2.0 * boost::math::cdf(boost::math::complement(t, std::abs(w.t))));
  return w;
}

std::optional<double> cohens_d(std::span<const double> a, std::span<const double> b) {
  if (a.size() < 2 || b.size() < 2) return std::nullopt;
  const double na = static_cast<double>(a.size());
  const double nb = static_cast<double>(b.size());
  const double pooled_variance = (squared_deviations(a, mean_of(a)) + squared_deviations(b, mean_of(b))) / (na + nb - 2.0);
  if (!(pooled_variance > 0.0) || !std::isfinite(pooled_variance)) return std::nullopt;
  const double d = (mean_of(a) - mean_of(b)) / std::sqrt(pooled_variance);
  if (!std::isfinite(d)) return std::nullopt;
  return d;
}

std::optional<double> pearson_correlation(std::span<const double> x, std::span<const double> y) {
  if (x.size() != y.size() || x.size() < 2) return std::nullopt;
  const double mx = mean_of(x);
  const double my = mean_of(y);
  double sxy = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) sxy += (x[i] - mx) * (y[i] - my);
  const double sxx = squared_deviations(x, mx);
  const double syy = squared_deviations(y, my);
  if (!(sxx > 0.0) || !(syy > 0.0)) return std::nullopt;
  const double r = sxy / std::sqrt(sxx * syy);
  if (!std::isfinite(r)) return std::nullopt;
  return std::clamp(r, -1.0, 1.0);
}

}  // namespace vimg::study
