#include "study/fit_likelihood.hpp"

#include <algorithm>
#include <cmath>

namespace vimg::study {

namespace {

double weight_scale(const DiscriminationConstants& defaults, std::size_t cue) {
  const double w0 = defaults.cue_weight[cue];
  return w0 > 0.0 ? w0 : 1.0;
}

}  // namespace

std::vector<ChoiceCounts> pooled_counts_of(const FitData& data, std::span<const std::size_t> chosen) {
  std::vector<ChoiceCounts> pooled;
  for (const CueMatrix& cues : data.set_cues) pooled.emplace_back(cues.size(), std::vector<double>(cues.size(), 0.0));
  for (const std::size_t p : chosen) {
    for (std::size_t s = 0; s < pooled.size(); ++s) {
      for (std::size_t i = 0; i < pooled[s].size(); ++i) {
        for (std::size_t j = 0; j < pooled[s].size(); ++j) pooled[s][i][j] += data.counts[p][s][i][j];
      }
    }
  }
  return pooled;
}

std::vector<ChoiceCounts> pooled_counts(const FitData& data, std::size_t left_out) {
  std::vector<std::size_t> chosen;
  for (std::size_t p = 0; p < data.counts.size(); ++p) {
    if (p != left_out) chosen.push_back(p);
  }
  return pooled_counts_of(data, chosen);
}

double set_trials(const ChoiceCounts& set) {
  double n = 0.0;
  for (const auto& row : set) {
    for (const double c : row) n += c;
  }
  return n;
}

double total_trials(const std::vector<ChoiceCounts>& counts) {
  double n = 0.0;
  for (const ChoiceCounts& set : counts) n += set_trials(set);
  return n;
}

double log_likelihood(const std::vector<CueMatrix>& set_cues, const std::vector<ChoiceCounts>& counts,
                      const DiscriminationConstants& constants) {
  double ll = 0.0;
  for (std::size_t s = 0; s < set_cues.size(); ++s) {
    if (set_trials(counts[s]) == 0.0) continue;
    const PerceptionMatrix p = identification_confusion(set_cues[s], constants);
    for (std::size_t i = 0; i < p.size(); ++i) {
      for (std::size_t j = 0; j < p.size(); ++j) {
        if (counts[s][i][j] > 0.0) ll += counts[s][i][j] * std::log(std::max(p[i][j], 1e-300));
      }
    }
  }
  return ll;
}

double chance_log_likelihood(const std::vector<ChoiceCounts>& counts) {
  double ll = 0.0;
  for (const ChoiceCounts& set : counts) {
    if (!set.empty()) ll -= set_trials(set) * std::log(static_cast<double>(set.size()));
  }
  return ll;
}

std::string fit_constant_name(std::size_t k) {
  return k == 0 ? std::string("lapse_rate") : "cue_weight." + std::string(cue_name(k - 1));
}

double constant_value(const DiscriminationConstants& constants, std::size_t k) {
  return k == 0 ? constants.lapse_rate : constants.cue_weight[k - 1];
}

void set_constant_value(DiscriminationConstants& constants, std::size_t k, double value) {
  (k == 0 ? constants.lapse_rate : constants.cue_weight[k - 1]) = value;
}

double theta_lower(std::size_t k) { return k == 0 ? -kLapseThetaBound : -kWeightThetaBound; }
double theta_upper(std::size_t k) { return k == 0 ? kLapseThetaBound : kWeightThetaBound; }

double to_theta(std::size_t k, double value, const DiscriminationConstants& defaults) {
  double theta = 0.0;
  if (k == 0) {
    const double share = value / kMaxFittedLapse;
    theta = share <= 0.0 ? -kLapseThetaBound : share >= 1.0 ? kLapseThetaBound : std::log(share / (1.0 - share));
  } else {
    theta = value > 0.0 ? std::log(value / weight_scale(defaults, k - 1)) : -kWeightThetaBound;
  }
  return std::clamp(theta, theta_lower(k), theta_upper(k));
}

double from_theta(std::size_t k, double theta, const DiscriminationConstants& defaults) {
  if (k == 0) return kMaxFittedLapse / (1.0 + std::exp(-theta));
  return weight_scale(defaults, k - 1) * std::exp(theta);
}

DiscriminationConstants constants_at(const DiscriminationConstants& defaults, const std::vector<std::size_t>& free,
                                     std::span<const double> theta) {
  DiscriminationConstants c = defaults;
  for (std::size_t m = 0; m < free.size(); ++m) set_constant_value(c, free[m], from_theta(free[m], theta[m], defaults));
  return c;
}

bool cue_separates_any_pair(const std::vector<CueMatrix>& set_cues, std::size_t cue) {
  for (const CueMatrix& cues : set_cues) {
    for (std::size_t i = 0; i < cues.size(); ++i) {
      for (std::size_t j = 0; j < cues.size(); ++j) {
        if (i != j && std::abs(cues[i][j][cue]) > 1e-9) return true;
      }
    }
  }
  return false;
}

}  // namespace vimg::study
