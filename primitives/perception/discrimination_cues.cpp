#include "primitives/perception/discrimination_cues.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

#include "primitives/perception/channel_levels.hpp"
#include "primitives/perception/hann_window.hpp"
#include "primitives/perception/perception_rate.hpp"
#include "primitives/perception/power_spectrum.hpp"

namespace vimg {

namespace {

constexpr std::size_t kN = kSpectrumFrameSamples;
static_assert(kN == detail::kPowerSpectrumFrameSamples);
constexpr std::size_t kBins = detail::kPowerSpectrumBins;
constexpr std::size_t kHop = kN / 2;
constexpr double kBinHz = kPerceptionRateHz / static_cast<double>(kN);
constexpr double kEnvelopeStepMs = 1000.0 * static_cast<double>(kEnvelopeStepSamples) / kPerceptionRateHz;
constexpr std::size_t kSlowEnvelopeStride = 8;  // steps between computed values of the slow envelope

// The level that stands for "no energy at all", dB.
constexpr double kSilentLevelDb = -400.0;

double to_db(double power) { return power > 0.0 ? 10.0 * std::log10(power) : kSilentLevelDb; }

// Per bin: (full-scale displacement / threshold)^2 of each channel.
struct ChannelGains {
  std::array<double, kBins> pacinian{};
  std::array<double, kBins> non_pacinian{};
};

ChannelGains channel_gains(const LevelCalibration& calibration) {
  ChannelGains g;
  for (std::size_t k = 1; k + 1 < kBins; ++k) {
    const double f = static_cast<double>(k) * kBinHz;
    if (f < kLowestFeltHz) continue;
    const double omega = 2.0 * std::numbers::pi * f;
    const double displacement_m = calibration.full_scale_peak_acceleration_mps2 / (omega * omega);
    const double p = displacement_m / threshold_peak_displacement_m(f, calibration);
    const double np = displacement_m / kNonPacinianThresholdPeakDisplacementM;
    g.pacinian[k] = p * p;
    g.non_pacinian[k] = np * np;
  }
  return g;
}

// A Hann window of `length` points (rounded), weights summing to 1.
std::vector<double> hann_window(double length) {
  const auto n = std::max<std::size_t>(1, static_cast<std::size_t>(std::lround(length)));
  std::vector<double> w(n);
  double total = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    w[i] = hann_sample(i, n, 0.5);
    total += w[i];
  }
  for (double& v : w) v /= total;
  return w;
}

// A track with the range of its values within +-kTimingToleranceMs of each step.
EnvelopeTrack envelope_track(std::vector<float> db, float silent_db) {
  EnvelopeTrack t;
  const std::size_t steps = db.size();
  const auto tolerance = static_cast<std::size_t>(kTimingToleranceMs / kEnvelopeStepMs);
  t.low_db.resize(steps);
  t.high_db.resize(steps);
  for (std::size_t s = 0; s < steps; ++s) {
    const std::size_t first = s > tolerance ? s - tolerance : 0;
    const std::size_t last = std::min(steps - 1, s + tolerance);
    const auto [low, high] = std::minmax_element(db.begin() + static_cast<std::ptrdiff_t>(first),
                                                 db.begin() + static_cast<std::ptrdiff_t>(last) + 1);
    t.low_db[s] = *low;
    t.high_db[s] = *high;
  }
  t.db = std::move(db);
  t.silent_db = silent_db;
  return t;
}

// The distance of x from the interval [low, high].
double outside(double x, double low, double high) { return x < low ? low - x : (x > high ? x - high : 0.0); }

}  // namespace

double skin_threshold_peak_displacement_m(double frequency_hz, const LevelCalibration& calibration) {
  return std::min(threshold_peak_displacement_m(frequency_hz, calibration), kNonPacinianThresholdPeakDisplacementM);
}

DiscriminationFeatures analyse_discrimination(std::span<const double> signal_8khz, const LevelCalibration& calibration) {
  DiscriminationFeatures f;
  const std::size_t size = signal_8khz.size();
  if (size == 0) return f;
  const ChannelGains gains = channel_gains(calibration);

  // Spectrum frames, centre j * kHop.
  const std::size_t frames = (size + kHop - 1) / kHop + 1;
  std::array<double, kBins> mean_excitation{};
  std::array<double, kN> frame{};
  std::array<double, kBins> power{};
  for (std::size_t j = 0; j < frames; ++j) {
    const std::ptrdiff_t start = static_cast<std::ptrdiff_t>(j * kHop) - static_cast<std::ptrdiff_t>(kN / 2);
    bool any = false;
    for (std::size_t n = 0; n < kN; ++n) {
      const std::ptrdiff_t i = start + static_cast<std::ptrdiff_t>(n);
      frame[n] = (i >= 0 && static_cast<std::size_t>(i) < size) ? signal_8khz[static_cast<std::size_t>(i)] : 0.0;
      any = any || frame[n] != 0.0;
    }
    if (!any) continue;
    detail::hann_power_spectrum(frame, power);
    for (std::size_t k = 1; k + 1 < kBins; ++k) {
      mean_excitation[k] += std::max(power[k] * gains.pacinian[k], power[k] * gains.non_pacinian[k]);
    }
  }
  // Level: each channel's, as it sums over time (channel_levels.hpp); felt through the more
  // sensitive one.
  const detail::ChannelLevels channels = detail::channel_levels(signal_8khz, calibration, kSlowEnvelopeWindowMs);
  f.pacinian_level_db = channels.pacinian_db;
  f.non_pacinian_level_db = channels.non_pacinian_db;
  f.level_db = std::max({0.0, channels.pacinian_db, channels.non_pacinian_db});
  f.moment_level_db = std::max({0.0, channels.pacinian_moment_db, channels.non_pacinian_db});

  // Envelopes: the Hann-weighted mean of x^2 around each step (fast), and that smoothed again over
  // kSlowEnvelopeWindowMs (slow), in dB relative to the slow one's largest value, floored where
  // they fall below the threshold (level_db below the strongest moment).
  const std::vector<double> window = hann_window(kEnvelopeWindowMs * kPerceptionRateHz / 1000.0);
  const std::size_t half = window.size() / 2;
  const std::size_t steps = (size + kEnvelopeStepSamples - 1) / kEnvelopeStepSamples;
  std::vector<double> fast(steps, 0.0);
  for (std::size_t s = 0; s < steps; ++s) {
    const std::size_t centre = s * kEnvelopeStepSamples;
    double mean_square = 0.0;
    for (std::size_t i = 0; i < window.size(); ++i) {
      const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(centre + i) - static_cast<std::ptrdiff_t>(half);
      if (n < 0 || static_cast<std::size_t>(n) >= size) continue;
      const double x = signal_8khz[static_cast<std::size_t>(n)];
      mean_square += window[i] * x * x;
    }
    fast[s] = mean_square;
  }
  const std::vector<double> slow_window = hann_window(kSlowEnvelopeWindowMs / kEnvelopeStepMs);
  const std::size_t slow_half = slow_window.size() / 2;
  // The slow envelope changes little within kSlowEnvelopeStride steps: computed there, linear between.
  const auto slow_at = [&](std::size_t s) {
    double mean = 0.0;
    for (std::size_t i = 0; i < slow_window.size(); ++i) {
      const std::ptrdiff_t k = static_cast<std::ptrdiff_t>(s + i) - static_cast<std::ptrdiff_t>(slow_half);
      if (k >= 0 && static_cast<std::size_t>(k) < steps) mean += slow_window[i] * fast[static_cast<std::size_t>(k)];
    }
    return mean;
  };
  std::vector<double> slow(steps, 0.0);
  double peak = 0.0;
  for (std::size_t s0 = 0; s0 < steps; s0 += kSlowEnvelopeStride) {
    const std::size_t s1 = std::min(s0 + kSlowEnvelopeStride, steps - 1);
    const double v0 = s0 == 0 ? slow_at(0) : slow[s0];
    const double v1 = slow_at(s1);
    for (std::size_t s = s0; s <= s1; ++s) {
      const double t = s1 > s0 ? static_cast<double>(s - s0) / static_cast<double>(s1 - s0) : 0.0;
      slow[s] = (1.0 - t) * v0 + t * v1;
      peak = std::max(peak, slow[s]);
    }
  }
  const double peak_db = to_db(peak);
  const auto relative = [&](double mean_square) { return std::max(to_db(mean_square) - peak_db, -f.moment_level_db); };
  // A dip: how far the fast envelope falls below the smaller of its largest values in the
  // kDipContextMs before and after (signal on both sides: a gap, not an onset or an end).
  const auto context = static_cast<std::size_t>(kDipContextMs / kEnvelopeStepMs);
  // A rhythm's gap: the same against the means over kRhythmContextMs before and after (silence
  // beyond the signal's ends): a gap between bursts too long for kDipContextMs and too short for the
  // slow envelope; means, so that a brief click beside it counts as little as it is felt.
  const auto rhythm_context = static_cast<std::size_t>(kRhythmContextMs / kEnvelopeStepMs);
  std::vector<double> running(steps + 1, 0.0);  // running[k]: the sum of fast[0..k)
  for (std::size_t s = 0; s < steps; ++s) running[s + 1] = running[s] + fast[s];
  const auto rhythm_mean = [&](std::size_t first, std::size_t end) {  // over [first, end) within the signal
    end = std::min(end, steps);
    return first < end ? std::max(0.0, running[end] - running[first]) / static_cast<double>(rhythm_context + 1) : 0.0;
  };
  std::vector<float> slow_db(steps), dips_db(steps), gaps_db(steps), silence_db(steps);
  for (std::size_t s = 0; s < steps; ++s) {
    double before = 0.0, after = 0.0;
    for (std::size_t k = s > context ? s - context : 0; k <= s; ++k) before = std::max(before, fast[k]);
    for (std::size_t k = s; k < steps && k <= s + context; ++k) after = std::max(after, fast[k]);
    slow_db[s] = static_cast<float>(relative(slow[s]));
    dips_db[s] = static_cast<float>(std::min(0.0, relative(fast[s]) - relative(std::min(before, after))));
    const double around = relative(std::min(rhythm_mean(s > rhythm_context ? s - rhythm_context : 0, s + 1),
                                            rhythm_mean(s, s + rhythm_context + 1)));
    gaps_db[s] = static_cast<float>(std::min(0.0, relative(fast[s]) - around));
    silence_db[s] = static_cast<float>(std::min(0.0, -f.moment_level_db - around));
  }
  f.slow_envelope = envelope_track(std::move(slow_db), static_cast<float>(-f.moment_level_db));
  f.dips = envelope_track(std::move(dips_db), 0.0f);
  f.rhythm = envelope_track(std::move(gaps_db), 0.0f);
  f.rhythm.silence_db = std::move(silence_db);

  // Pitch: the excitation-weighted mean of log2 f over the frame-averaged spectrum.
  if (f.level_db > 0.0) {
    double weight = 0.0, moment = 0.0;
    for (std::size_t k = 1; k + 1 < kBins; ++k) {
      weight += mean_excitation[k];
      moment += mean_excitation[k] * std::log2(static_cast<double>(k) * kBinHz);
    }
    if (weight > 0.0) f.pitch_octaves = moment / weight;
  }
  return f;
}

std::string_view cue_name(std::size_t cue) {
  static constexpr std::array<std::string_view, kCueCount> names = {"level", "pitch", "envelope"};
  return cue < kCueCount ? names[cue] : std::string_view{};
}

namespace {

// The largest amount by which a moment of one track lies outside the other's range within
// +-kTimingToleranceMs (beyond a signal's ends its track is silence), weighted by how strongly that
// moment is felt: min(1, level / kFullSalienceLevelDb), the felt level of the stronger of the two
// slow envelopes there (near threshold a difference counts less; where neither is felt, not at all).
double track_distance_db(const DiscriminationFeatures& a, const DiscriminationFeatures& b, EnvelopeTrack DiscriminationFeatures::*track) {
  const auto one_way = [track](const DiscriminationFeatures& x, const DiscriminationFeatures& y) {
    const EnvelopeTrack& tx = x.*track;
    const EnvelopeTrack& ty = y.*track;
    const std::size_t steps = std::max(tx.db.size(), ty.db.size());
    const std::size_t y_size = ty.db.size();
    const auto tolerance = static_cast<std::size_t>(kTimingToleranceMs / kEnvelopeStepMs);
    const auto felt = [](const DiscriminationFeatures& z, std::size_t s) {
      return z.moment_level_db + (s < z.slow_envelope.db.size() ? static_cast<double>(z.slow_envelope.high_db[s]) : -z.moment_level_db);
    };
    const auto silence_at = [](const EnvelopeTrack& t, std::size_t s) {
      return s < t.silence_db.size() ? static_cast<double>(t.silence_db[s]) : -std::numeric_limits<double>::infinity();
    };
    double worst = 0.0;
    for (std::size_t s = 0; s < steps; ++s) {
      const double v = s < tx.db.size() ? static_cast<double>(tx.db[s]) : tx.silent_db;
      double low = ty.silent_db, high = ty.silent_db;
      if (s < y_size) {
        low = ty.low_db[s];
        high = ty.high_db[s];
      }
      // Near y's start and end its range takes in the silence before and after it.
      if (s < tolerance || s + tolerance >= y_size) {
        low = std::min(low, static_cast<double>(ty.silent_db));
        high = std::max(high, static_cast<double>(ty.silent_db));
      }
      // Rhythm: gaps down to silence in both are alike (the shallower of the two silences).
      const double floor = std::max(silence_at(tx, s), silence_at(ty, s));
      const double salience = std::clamp(std::max(felt(x, s), felt(y, s)) / kFullSalienceLevelDb, 0.0, 1.0);
      worst = std::max(worst, outside(std::max(v, floor), std::max(low, floor), std::max(high, floor)) * salience);
    }
    return worst;
  };
  return std::max(one_way(a, b), one_way(b, a));
}

}  // namespace

CueDistances cue_distances(const DiscriminationFeatures& a, const DiscriminationFeatures& b) {
  CueDistances d{};
  d[static_cast<std::size_t>(Cue::level)] = std::abs(a.level_db - b.level_db) / kLevelJndDb;
  const double felt = std::min(a.level_db, b.level_db);
  if (felt > 0.0) {
    const double pitch_jnd_octaves = std::log2(1.0 + kFrequencyWeberFraction);
    d[static_cast<std::size_t>(Cue::pitch)] =
        std::abs(a.pitch_octaves - b.pitch_octaves) / pitch_jnd_octaves * std::min(1.0, felt / kFullSalienceLevelDb);
  }
  d[static_cast<std::size_t>(Cue::envelope)] =
      std::max({track_distance_db(a, b, &DiscriminationFeatures::slow_envelope), track_distance_db(a, b, &DiscriminationFeatures::dips),
                track_distance_db(a, b, &DiscriminationFeatures::rhythm)}) /
      kLevelJndDb;
  return d;
}

void fill_cue_matrix_row(std::span<const DiscriminationFeatures> signals, std::size_t i, CueMatrix& m) {
  for (std::size_t j = i + 1; j < signals.size(); ++j) m[i][j] = cue_distances(signals[i], signals[j]);
}

void mirror_cue_matrix(CueMatrix& m) {
  for (std::size_t i = 0; i < m.size(); ++i) {
    m[i][i] = CueDistances{};
    for (std::size_t j = 0; j < i; ++j) m[i][j] = m[j][i];
  }
}

CueMatrix cue_matrix(std::span<const DiscriminationFeatures> signals) {
  const std::size_t n = signals.size();
  CueMatrix m(n, std::vector<CueDistances>(n, CueDistances{}));
  for (std::size_t i = 0; i < n; ++i) fill_cue_matrix_row(signals, i, m);
  mirror_cue_matrix(m);
  return m;
}

}  // namespace vimg
