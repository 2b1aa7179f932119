#pragma once
// The state the search of separate_search.hpp moves, its score, and the moves it considers
// (internal to separate_search.cpp and its tests' exhaustive counterpart).
//
// Threads: one caller at a time.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <memory>
#include <vector>

#include "study/separate_search.hpp"

namespace vimg::study::search_detail {

inline constexpr double kEpsilon = 1e-12;


inline int raw_steps(const SeparationSetting& s) {
  int n = 0;
  for (std::size_t p = 0; p < kTactileParameterCount; ++p) {
    if (is_choice_parameter(static_cast<TactileParameter>(p))) {
      n += s[p] != 0 ? 1 : 0;
    } else {
      n += std::abs(static_cast<int>(s[p]));
    }
  }
  return n;
}

inline double shortfall_of(const std::vector<double>& diagonal, double target) {
  double s = 0.0;
  for (const double p : diagonal) s += std::max(0.0, target - p);
  return s;
}

struct Score {
  double shortfall = 0.0;
  double cost = 0.0;  // with the tie-break
  std::vector<double> diagonal;
};

// The state being searched, its cue matrix and per-image change, and the score of one-image moves.
class State {
 public:
  // `counter`: counts every state scored (shared by copies and by other states).
  State(SeparationSpace& space, const SeparationRequest& request, std::vector<SeparationSetting> settings, int* counter)
      : space_(&space), request_(&request), settings_(std::move(settings)), evaluations_(counter) {
    const std::size_t n = settings_.size();
    cues_.assign(n, std::vector<CueDistances>(n, CueDistances{}));
    change_.assign(n, 0.0);
    for (std::size_t i = 0; i < n; ++i) {
      change_[i] = space_->change_jnd(i, settings_[i]);
      for (std::size_t j = i + 1; j < n; ++j) cues_[i][j] = cues_[j][i] = space_->cues(i, settings_[i], j, settings_[j]);
    }
    score_ = score_of(cues_, change_, settings_);
  }

  const Score& score() const { return score_; }
  const std::vector<SeparationSetting>& settings() const { return settings_; }
  const std::vector<double>& change() const { return change_; }

  // The score if image i took `setting`.
  Score with(std::size_t i, const SeparationSetting& setting) {
    CueMatrix cues = cues_;
    std::vector<double> change = change_;
    std::vector<SeparationSetting> settings = settings_;
    replace(i, setting, cues, change, settings);
    return score_of(cues, change, settings);
  }

  void apply(std::size_t i, const SeparationSetting& setting) {
    replace(i, setting, cues_, change_, settings_);
    score_ = score_of(cues_, change_, settings_);
  }

 private:
  void replace(std::size_t i, const SeparationSetting& setting, CueMatrix& cues, std::vector<double>& change,
               std::vector<SeparationSetting>& settings) {
    settings[i] = setting;
    change[i] = space_->change_jnd(i, setting);
    for (std::size_t j = 0; j < settings.size(); ++j) {
      if (j == i) continue;
      cues[i][j] = cues[j][i] = space_->cues(i, setting, j, settings[j]);
    }
  }

  Score score_of(const CueMatrix& cues, const std::vector<double>& change, const std::vector<SeparationSetting>& settings) {
    ++*evaluations_;
    Score s;
    const PerceptionMatrix confusion = identification_confusion(cues, request_->constants);
    for (std::size_t i = 0; i < confusion.size(); ++i) s.diagonal.push_back(confusion[i][i]);
    s.shortfall = shortfall_of(s.diagonal, request_->target);
    for (std::size_t i = 0; i < change.size(); ++i) s.cost += change[i] + kStepTieBreak * raw_steps(settings[i]);
    return s;
  }

  SeparationSpace* space_;
  const SeparationRequest* request_;
  std::vector<SeparationSetting> settings_;
  CueMatrix cues_;
  std::vector<double> change_;
  Score score_;
  int* evaluations_;
};

inline bool movable(const SeparationRequest& r, std::size_t image, std::size_t p) {
  if (!r.keep.empty() && r.keep[image]) return false;
  if (!r.vary[p]) return false;
  return r.present.empty() || r.present[image][p];
}

// Image i's setting with parameter p at each of `values`, those the space allows, appended to out.
inline void add_moves(SeparationSpace& space, std::size_t i, const SeparationSetting& now, std::size_t p,
                      const std::vector<int>& values, std::vector<SeparationCandidate>& out) {
  for (const int v : values) {
    SeparationSetting s = now;
    s[p] = static_cast<std::int8_t>(v);
    if (space.allowed(i, s)) out.push_back({i, s});
  }
}

// Moves of every movable image: the neighbours along each parameter (a choice: every other value);
// `long_moves`: every value that is not a neighbour instead; `back`: the original value of each
// moved parameter too; `toward_origin`: only one step toward the original value (a choice: back
// to it).
inline std::vector<SeparationCandidate> moves(SeparationSpace& space, const SeparationRequest& r,
                                       const std::vector<SeparationSetting>& state, bool long_moves, bool back,
                                       bool toward_origin = false, std::size_t frozen = SIZE_MAX) {
  std::vector<SeparationCandidate> out;
  for (std::size_t i = 0; i < state.size(); ++i) {
    if (i == frozen) continue;
    for (std::size_t p = 0; p < kTactileParameterCount; ++p) {
      if (!movable(r, i, p)) continue;
      const TactileParameter param = static_cast<TactileParameter>(p);
      const StepRange range = step_range(param);
      const int now = state[i][p];
      std::vector<int> values;
      for (int v = range.lowest; v <= range.highest; ++v) {
        if (v == now) continue;
        const bool neighbour = is_choice_parameter(param) || std::abs(v - now) == 1;
        if (toward_origin) {
          const bool back_one = is_choice_parameter(param) ? v == 0 : std::abs(v) < std::abs(now) && std::abs(v - now) == 1;
          if (back_one) values.push_back(v);
        } else if (long_moves ? !neighbour : (neighbour || (back && v == 0))) {
          values.push_back(v);
        }
      }
      add_moves(space, i, state[i], p, values, out);
    }
  }
  return out;
}

// The exchange phase's candidates: every image moved along one parameter, the nearest values
// first and the images interleaved (distance 1 of every image, then 2, ...), so that a budget that
// runs out has tried each image alike. A choice's values count as distance 1.
inline std::vector<SeparationCandidate> exchange_moves(SeparationSpace& space, const SeparationRequest& r,
                                                       const std::vector<SeparationSetting>& state) {
  std::vector<SeparationCandidate> out;
  int widest = 0;
  for (std::size_t p = 0; p < kTactileParameterCount; ++p) {
    const StepRange range = step_range(static_cast<TactileParameter>(p));
    widest = std::max(widest, range.highest - range.lowest);
  }
  for (int d = 1; d <= widest; ++d) {
    for (std::size_t i = 0; i < state.size(); ++i) {
      for (std::size_t p = 0; p < kTactileParameterCount; ++p) {
        if (!movable(r, i, p)) continue;
        const TactileParameter param = static_cast<TactileParameter>(p);
        const StepRange range = step_range(param);
        const int now = state[i][p];
        std::vector<int> values;
        if (is_choice_parameter(param)) {
          if (d == 1)
            for (int v = range.lowest; v <= range.highest; ++v)
              if (v != now) values.push_back(v);
        } else {
          for (const int v : {now - d, now + d})
            if (v >= range.lowest && v <= range.highest) values.push_back(v);
        }
        add_moves(space, i, state[i], p, values, out);
      }
    }
  }
  return out;
}

struct Choice {
  std::size_t index = 0;
  Score score;
  bool found = false;
};

// Phase 1: the move that lowers the shortfall most per unit of change (a free one first).
inline Choice best_ascent(State& state, const std::vector<SeparationCandidate>& batch) {
  Choice best;
  double best_free = 0.0;
  double best_ratio = 0.0;
  bool have_free = false;
  const Score& now = state.score();
  for (std::size_t k = 0; k < batch.size(); ++k) {
    Score s = state.with(batch[k].image, batch[k].setting);
    const double gain = now.shortfall - s.shortfall;
    if (gain <= kEpsilon) continue;
    const double added = s.cost - now.cost;
    if (added <= 0.0) {
      if (!have_free || gain > best_free) {
        have_free = true;
        best_free = gain;
        best = {k, std::move(s), true};
      }
    } else if (!have_free) {
      const double ratio = gain / added;
      if (!best.found || ratio > best_ratio) {
        best_ratio = ratio;
        best = {k, std::move(s), true};
      }
    }
  }
  return best;
}

// Phase 2: the move that lowers the change most without raising the shortfall.
inline Choice best_pruning(State& state, const std::vector<SeparationCandidate>& batch) {
  Choice best;
  const Score& now = state.score();
  double best_drop = 1e-9;
  for (std::size_t k = 0; k < batch.size(); ++k) {
    Score s = state.with(batch[k].image, batch[k].setting);
    if (s.shortfall > now.shortfall + kEpsilon) continue;
    const double drop = now.cost - s.cost;
    if (drop > best_drop) {
      best_drop = drop;
      best = {k, std::move(s), true};
    }
  }
  return best;
}

inline SeparationOutcome outcome_of(const State& state, int evaluations) {
  SeparationOutcome o;
  o.settings = state.settings();
  o.identified = state.score().diagonal;
  o.change_jnd = state.change();
  o.shortfall = state.score().shortfall;
  for (std::size_t i = 0; i < o.change_jnd.size(); ++i) o.total_change_jnd += o.change_jnd[i];
  o.reached = o.shortfall <= kEpsilon;
  o.evaluations = evaluations;
  return o;
}


}  // namespace vimg::study::search_detail
