#pragma once
// The statistics of the study reports (docs/studies.md "Statistics"), as pure functions. The
// distributions (normal and Student t quantiles, the t survival function) are Boost.Math's; nothing
// here is a hand-written special function. Every function that is undefined for its input (too few
// values, no variance) says so with std::nullopt instead of returning NaN.
//
//   mean and SD:   mean = sum x / n,  SD = sqrt(sum (x - mean)^2 / (n - 1))           (n >= 2 for the SD)
//   Wilson:        p = k/n, z = Phi^-1((1 + level)/2);
//                  centre = (p + z^2/(2n)) / (1 + z^2/n),
//                  half   = z / (1 + z^2/n) * sqrt(p(1 - p)/n + z^2/(4n^2))
//   t interval:    mean -+ t_{(1 + level)/2, n-1} * SD / sqrt(n)                       (two-sided)
//   Welch:         t = (mean_a - mean_b) / sqrt(va/na + vb/nb),
//                  df = (va/na + vb/nb)^2 / ((va/na)^2/(na-1) + (vb/nb)^2/(nb-1)),
//                  p = 2 * P(T_df > |t|)                                                 (two-sided)
//   Cohen's d:     (mean_a - mean_b) / s_pooled, s_pooled = sqrt(((na-1)va + (nb-1)vb) / (na + nb - 2))
//   Pearson r:     sum (x - mx)(y - my) / sqrt(sum (x - mx)^2 * sum (y - my)^2)
#include <cstddef>
#include <optional>
#include <span>

namespace vimg::study {

struct Interval {
  double lower = 0.0;
  double upper = 0.0;
};

struct Summary {
  std::size_t n = 0;
  double mean = 0.0;             // 0 when n == 0
  std::optional<double> sd;      // sample SD (n - 1 in the denominator); none when n < 2
};

Summary summarize(std::span<const double> values);

// The Wilson score interval of a proportion `successes` / `trials` at confidence `level` in (0, 1)
// (0.95 for the reports). None when trials == 0 or successes > trials.
std::optional<Interval> wilson_interval(std::size_t successes, std::size_t trials, double level = 0.95);

// The two-sided Student t interval of a mean from n values with sample SD `sd`, at `level` in (0, 1).
// None when n < 2 or sd is negative or not finite.
std::optional<Interval> t_interval_of_mean(double mean, double sd, std::size_t n, double level);
std::optional<Interval> t_interval_of_mean(std::span<const double> values, double level);

struct WelchTest {
  double t = 0.0;
  double df = 0.0;  // Welch-Satterthwaite
  double p = 1.0;   // two-sided
};

// Welch's unequal-variance t-test of mean(a) against mean(b). None when either group has fewer
// than two values or both have no variance (t is then 0/0).
std::optional<WelchTest> welch_t_test(std::span<const double> a, std::span<const double> b);

// Cohen's d of a against b with the pooled SD above (the classic d, not Hedges' g, not Glass's
// delta). None when either group has fewer than two values or the pooled SD is 0.
std::optional<double> cohens_d(std::span<const double> a, std::span<const double> b);

// Pearson's correlation of paired values. None when the sizes differ, n < 2, or either has no
// variance.
std::optional<double> pearson_correlation(std::span<const double> x, std::span<const double> y);

}  // namespace vimg::study
