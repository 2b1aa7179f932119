#include "primitives/perception/identification_choice.hpp"

#include <algorithm>
#include <cmath>

namespace vimg {

namespace {

double non_negative(double x) { return std::isnan(x) || x < 0.0 ? 0.0 : x; }

// ln(Phi(-x / 2) / Phi(x / 2)) for x >= 0, through erfc (no cancellation for large x); -inf once
// the tail underflows, which exp() turns back into a confusability of 0.
double log_confusability(double d_prime) {
  const double tail = 0.5 * std::erfc(d_prime / (2.0 * std::sqrt(2.0)));
  return std::log(tail) - std::log1p(-tail);
}

}  // namespace

std::array<double, kCueCount> cue_ranges_jnd(const CueMatrix& d) {
  std::array<double, kCueCount> r{};
  for (const auto& row : d)
    for (const CueDistances& pair : row)
      for (std::size_t c = 0; c < kCueCount; ++c) r[c] = std::max(r[c], non_negative(pair[c]));
  return r;
}

std::array<double, kCueCount> identification_d_primes(const CueDistances& d, const std::array<double, kCueCount>& ranges_jnd,
                                                      const DiscriminationConstants& k) {
  std::array<double, kCueCount> d_primes{};
  for (std::size_t c = 0; c < kCueCount; ++c) {
    const double w = non_negative(k.cue_weight[c]);
    const double range = kContextNoisePerDPrime * kDPrimePerJnd * w * non_negative(ranges_jnd[c]);
    d_primes[c] = kDPrimePerJnd * w * non_negative(d[c]) / std::sqrt(1.0 + range * range);
  }
  return d_primes;
}

double identification_confusability(const std::array<double, kCueCount>& d_primes) {
  double log_eta = 0.0;
  for (const double d_prime : d_primes) log_eta += log_confusability(non_negative(d_prime));
  return std::exp(log_eta);
}

PerceptionMatrix identification_confusion(const CueMatrix& d, const DiscriminationConstants& k) {
  const std::size_t n = d.size();
  const double guess = std::isnan(k.lapse_rate) ? 0.0 : std::clamp(k.lapse_rate, 0.0, 1.0);
  const std::array<double, kCueCount> ranges = cue_ranges_jnd(d);
  PerceptionMatrix p(n, std::vector<double>(n, 0.0));
  for (std::size_t i = 0; i < n; ++i) {
    double total = 0.0;
    for (std::size_t j = 0; j < n; ++j) {
      p[i][j] = i == j ? 1.0 : j < d[i].size() ? identification_confusability(identification_d_primes(d[i][j], ranges, k)) : 0.0;
      total += p[i][j];
    }
    for (double& value : p[i]) value = (1.0 - guess) * value / total + guess / static_cast<double>(n);
  }
  return p;
}

}  // namespace vimg
