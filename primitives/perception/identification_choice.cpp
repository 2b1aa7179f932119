#include "primitives/perception/identification_choice.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace vimg {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

double non_negative(double x) { return std::isnan(x) || x < 0.0 ? 0.0 : x; }

// P(lo < Z < hi) for a standard normal Z, from the tail nearer to the interval (no cancellation
// between two values near 1).
double interval_mass(double lo, double hi) {
  if (!(hi > lo)) return 0.0;
  const auto upper_tail = [](double x) { return 0.5 * std::erfc(x / std::sqrt(2.0)); };
  if (lo >= 0.0) return upper_tail(lo) - upper_tail(hi);
  if (hi <= 0.0) return upper_tail(-hi) - upper_tail(-lo);
  return 1.0 - upper_tail(-lo) - upper_tail(hi);
}

// d'_c of every pair of a set, n x n, +inf where the cue matrix has no entry.
class DPrimeTable {
 public:
  DPrimeTable(const CueMatrix& d, const DiscriminationConstants& k) : n_(d.size()), v_(n_ * n_), main_cues_(n_ * n_, 0) {
    const std::array<double, kCueCount> ranges = cue_ranges_jnd(d);
    for (std::size_t i = 0; i < n_; ++i) {
      for (std::size_t j = 0; j < n_; ++j) {
        if (j < d[i].size()) v_[i * n_ + j] = identification_d_primes(d[i][j], ranges, k);
        else v_[i * n_ + j].fill(kInfinity);
        for (std::size_t c = 0; c < kCueCount; ++c)
          if (differs_most(i, j, c)) main_cues_[i * n_ + j] |= 1u << c;
      }
    }
  }
  std::size_t size() const { return n_; }
  double at(std::size_t i, std::size_t j, std::size_t c) const { return v_[i * n_ + j][c]; }
  // Whether cue c is where i and j differ most: one cue per pair, the first of equals (read from
  // a mask made once per pair, not worked out again by every cell that asks).
  bool differ_most_on(std::size_t i, std::size_t j, std::size_t c) const { return (main_cues_[i * n_ + j] >> c) & 1u; }
  // The distance of i and j on every cue but c, squared, Euclidean in d'.
  double off_cue_squared(std::size_t i, std::size_t j, std::size_t c) const {
    double sum = 0.0;
    for (std::size_t other = 0; other < kCueCount; ++other)
      if (other != c) sum += at(i, j, other) * at(i, j, other);
    return sum;
  }

 private:
  std::size_t n_;
  std::vector<std::array<double, kCueCount>> v_;
  bool differs_most(std::size_t i, std::size_t j, std::size_t c) const {
    for (std::size_t other = 0; other < kCueCount; ++other)
      if (at(i, j, other) > at(i, j, c) || (other < c && at(i, j, other) == at(i, j, c))) return false;
    return true;
  }

  std::vector<unsigned> main_cues_;  // per pair, bit c set when differs_most(i, j, c)
};

// M_c(r | i, partner) of the header: the chance, under i's noise on cue c, that the observation
// falls in r's cell along c.
double cell_mass(const DPrimeTable& dp, std::size_t r, std::size_t i, std::size_t partner, std::size_t c) {
  const std::size_t n = dp.size();
  const auto bounds = [&](std::size_t k) {
    const double s = dp.at(r, k, c);
    return k != r && s > 0.0 && std::isfinite(s) && (k == partner || dp.differ_most_on(r, k, c));
  };
  std::size_t nearest = n;
  for (std::size_t k = 0; k < n; ++k)
    if (bounds(k) && (nearest == n || dp.at(r, k, c) < dp.at(r, nearest, c))) nearest = k;
  if (nearest == n) return 1.0;
  const double nearest_s = dp.at(r, nearest, c);
  // The cue's distances read as positions on a line: k lies on the nearest one's side of r when
  // its projection on the axis from r to the nearest is positive (law of cosines); on a line that
  // is exact, the far side giving -s rather than a rounding of 0.
  const auto on_nearest_side = [&](std::size_t k, double s) {
    const double to_nearest = dp.at(nearest, k, c);
    return k == nearest || to_nearest * to_nearest < s * s + nearest_s * nearest_s;
  };
  double half_near = kInfinity, half_far = kInfinity;
  for (std::size_t k = 0; k < n; ++k) {
    if (!bounds(k)) continue;
    const double s = dp.at(r, k, c);
    const double half = k == partner ? s / 2.0 : (s * s + dp.off_cue_squared(r, k, c)) / (2.0 * s);
    double& side = on_nearest_side(k, s) ? half_near : half_far;
    side = std::min(side, half);
  }
  const double from_r = dp.at(i, r, c);
  const double x = from_r > 0.0 && !on_nearest_side(i, from_r) ? -from_r : from_r;
  return interval_mass(-half_far - x, half_near - x);
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

PerceptionMatrix identification_confusion(const CueMatrix& d, const DiscriminationConstants& k) {
  const std::size_t n = d.size();
  const double guess = std::isnan(k.lapse_rate) ? 0.0 : std::clamp(k.lapse_rate, 0.0, 1.0);
  const DPrimeTable dp(d, k);
  PerceptionMatrix p(n, std::vector<double>(n, 0.0));
  for (std::size_t i = 0; i < n; ++i) {
    double total = 0.0;
    for (std::size_t j = 0; j < n; ++j) {
      double log_eta = 0.0;
      for (std::size_t c = 0; c < kCueCount && i != j; ++c) {
        if (!(dp.at(i, j, c) > 0.0)) continue;
        const double own = cell_mass(dp, i, i, j, c);  // > 0: i's own cell always has width
        if (own > 0.0) log_eta += std::log(cell_mass(dp, j, i, i, c)) - std::log(own);
      }
      p[i][j] = std::exp(log_eta);
      total += p[i][j];
    }
    for (double& value : p[i]) value = (1.0 - guess) * value / total + guess / static_cast<double>(n);
  }
  return p;
}

}  // namespace vimg
