#include "study/separate_search.hpp"

#include "study/separate_search_state.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <memory>

namespace vimg::study {

using namespace search_detail;


std::vector<double> identified_shares(SeparationSpace& space, const std::vector<SeparationSetting>& state,
                                      const DiscriminationConstants& constants) {
  const std::size_t n = state.size();
  CueMatrix cues(n, std::vector<CueDistances>(n, CueDistances{}));
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) cues[i][j] = cues[j][i] = space.cues(i, state[i], j, state[j]);
  const PerceptionMatrix confusion = identification_confusion(cues, constants);
  std::vector<double> out;
  for (std::size_t i = 0; i < n; ++i) out.push_back(confusion[i][i]);
  return out;
}

namespace {

// The search's phases over one state; each returns false when the space said stop.
class Search {
 public:
  Search(SeparationSpace& space, const SeparationRequest& request) : space_(space), request_(request) {}

  State start(std::vector<SeparationSetting> settings) { return State(space_, request_, std::move(settings), &evaluations_); }
  int evaluations() const { return evaluations_; }

  // Phase 1: while the target is not reached, the move that lowers the shortfall most per unit of
  // change (one step; when none helps, any length along one parameter).
  bool ascend(State& state, bool report) {
    for (int guard = 0; state.score().shortfall > kEpsilon && guard < request_.max_moves; ++guard) {
      std::vector<SeparationCandidate> batch = moves(space_, request_, state.settings(), false, false);
      if (!space_.prepare(batch, state.settings())) return false;
      Choice c = best_ascent(state, batch);
      if (!c.found) {
        batch = moves(space_, request_, state.settings(), true, false);
        if (!space_.prepare(batch, state.settings())) return false;
        c = best_ascent(state, batch);
      }
      if (!c.found) break;
      state.apply(batch[c.index].image, batch[c.index].setting);
      if (report) report_move(state, 1);
    }
    return true;
  }

  // Phase 2: while a move lowers the change without raising the shortfall, the one that lowers it
  // most (`toward_origin`: only steps back toward the designer's values; `frozen`: an image that
  // stays as it is).
  bool prune(State& state, bool toward_origin, bool report, std::size_t frozen = SIZE_MAX) {
    for (int guard = 0; guard < 4 * request_.max_moves; ++guard) {
      const std::vector<SeparationCandidate> batch =
          moves(space_, request_, state.settings(), false, true, toward_origin, frozen);
      if (!space_.prepare(batch, state.settings())) return false;
      const Choice c = best_pruning(state, batch);
      if (!c.found) return true;
      state.apply(batch[c.index].image, batch[c.index].setting);
      if (report) report_move(state, 2);
    }
    return true;
  }

  // Phase 3 (separate_search.hpp).
  bool exchange(State& state) {
    for (int round = 0; round < request_.max_moves; ++round) {
      const std::vector<SeparationCandidate> all = exchange_moves(space_, request_, state.settings());
      bool improved = false;
      for (const bool restart : {false, true}) {
        if (!try_exchanges(state, all, restart, improved)) return false;
        if (improved) break;
      }
      if (!improved) return true;
      report_move(state, 3);
    }
    return true;
  }

 private:
  // Tries the candidates in order, a chunk prepared at a time, until one improves `state`.
  bool try_exchanges(State& state, const std::vector<SeparationCandidate>& all, bool restart, bool& improved) {
    constexpr std::size_t kChunk = 8;
    for (std::size_t k = 0; k < all.size(); k += kChunk) {
      if (!space_.may_explore()) return true;
      const std::vector<SeparationCandidate> chunk(all.begin() + static_cast<std::ptrdiff_t>(k),
                                                   all.begin() + static_cast<std::ptrdiff_t>(std::min(all.size(), k + kChunk)));
      if (!space_.prepare(chunk, state.settings())) return false;
      for (const SeparationCandidate& c : chunk) {
        if (state.with(c.image, c.setting).shortfall > state.score().shortfall + kEpsilon && !restart) continue;
        State trial = state;
        if (!restart) {
          trial.apply(c.image, c.setting);
          if (!prune(trial, true, false, c.image)) return false;
        } else {
          std::vector<SeparationSetting> fresh(state.settings().size(), SeparationSetting{});
          fresh[c.image] = c.setting;
          trial = start(std::move(fresh));
          if (!ascend(trial, false) || !prune(trial, false, false)) return false;
        }
        if (trial.score().shortfall <= state.score().shortfall + kEpsilon &&
            trial.score().cost < state.score().cost - 1e-9) {
          state = trial;
          improved = true;
          return true;
        }
        if (!space_.may_explore()) return true;
      }
    }
    return true;
  }

  void report_move(const State& state, int phase) {
    ++moves_;
    if (request_.progress) request_.progress(phase, moves_, state.score().shortfall, state.score().cost);
  }

  SeparationSpace& space_;
  const SeparationRequest& request_;
  int moves_ = 0;
  int evaluations_ = 0;
};

}  // namespace

SeparationOutcome run_separation_search(SeparationSpace& space, const SeparationRequest& request) {
  const std::size_t n = space.image_count();
  std::vector<SeparationSetting> origin(n, SeparationSetting{});
  if (!space.prepare({}, origin)) {
    SeparationOutcome o;
    o.interrupted = true;
    return o;
  }
  Search search(space, request);
  State state = search.start(origin);
  const bool done = search.ascend(state, true) && search.prune(state, false, true) && search.exchange(state) &&
                    search.prune(state, false, true);
  SeparationOutcome o = outcome_of(state, search.evaluations());
  o.interrupted = !done;
  return o;
}

SeparationOutcome exhaustive_separation(SeparationSpace& space, const SeparationRequest& request,
                                        const std::vector<std::vector<SeparationSetting>>& choices) {
  const std::size_t n = choices.size();
  std::vector<std::size_t> index(n, 0);
  std::vector<SeparationSetting> settings(n);
  bool have = false;
  SeparationOutcome best;
  double best_cost = std::numeric_limits<double>::infinity();
  int evaluations = 0;
  while (true) {
    for (std::size_t i = 0; i < n; ++i) settings[i] = choices[i][index[i]];
    State state(space, request, settings, &evaluations);
    const Score& s = state.score();
    const bool better = !have || (s.shortfall < best.shortfall - kEpsilon) ||
                        (std::abs(s.shortfall - best.shortfall) <= kEpsilon && s.cost < best_cost);
    if (better) {
      have = true;
      best = outcome_of(state, 0);
      best_cost = s.cost;
    }
    std::size_t k = 0;
    while (k < n && ++index[k] == choices[k].size()) index[k++] = 0;
    if (k == n) break;
  }
  best.evaluations = evaluations;
  return best;
}

}  // namespace vimg::study
