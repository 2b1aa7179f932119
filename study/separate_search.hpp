#pragma once
// The search of `vimg separate` (docs/separate.md, "The search"): the smallest change of a set's
// tactile parameters, in what people feel, that brings every image to the target share identified.
//
//   state     one SeparationSetting per image (separate_space.hpp); all 0: the designer's set
//   p_ii      the diagonal of the predicted confusion (identification_confusion of the cue matrix)
//   shortfall S = sum_i max(0, target - p_ii)                         (0: the target is reached)
//   change    C = sum_i change_jnd_i + kStepTieBreak * sum_i sum_p |step_ip|
//             change_jnd_i: the combined distance (JNDs of the model) of image i's proposal from its
//             original; the tie-break prefers fewer raw steps among changes felt alike
//
// Greedy ascent, then pruning:
//   1. While S > 0: of every move of one image by one step of one parameter (a choice: to any other
//      value), take the one that lowers S most per unit of C it adds (a move that lowers both is
//      taken first, the largest drop of S). When no one-step move lowers S, moves of any length
//      along one parameter are tried; when none lowers S either, the target is out of reach and the
//      state of least S is kept.
//   2. While a move lowers C without raising S (one step, or back to the original value of a
//      parameter), take the one that lowers C most.
//   3. Exchange: one image moved along one parameter (the nearest values first, the images taken in
//      turn), then (a) the others pruned one step at a time back toward their originals, or, when
//      no such move helps, (b) the others started again from their originals through 1 and 2; the
//      first that leaves S no larger for less C is kept and the round starts again. It ends when
//      a round finds nothing or the space's budget is spent (may_explore), and is followed by 2.
//      Greedy ascent alone is myopic (it spends one step at a time where one larger change of
//      another image would do); 3 repairs that: on the tests' small cases the result is within
//      10 % of exhaustive search over the same steps (tests/separate/separate_search_test.cpp).
// The search is deterministic: candidates are visited in a fixed order and ties go to the first.
//
// Threads: run_separation_search calls the space from the calling thread only; a space may use
// threads inside prepare().
#include <cstddef>
#include <functional>
#include <vector>

#include "primitives/perception/discrimination_choice.hpp"
#include "primitives/perception/identification_choice.hpp"
#include "study/separate_space.hpp"

namespace vimg::study {

inline constexpr double kStepTieBreak = 1e-3;
// The default target: every image identified at least 90 % of the time (`vimg separate --target`,
// and the share below which `vimg study report` points a set's prediction to `vimg separate`).
inline constexpr double kIdentifiedTarget = 0.9;

// One image at one setting.
struct SeparationCandidate {
  std::size_t image = 0;
  SeparationSetting setting{};
};

// What the search asks of the images. The real one renders (separate.cpp); tests use analytic ones.
class SeparationSpace {
 public:
  virtual ~SeparationSpace() = default;
  virtual std::size_t image_count() const = 0;
  // Whether image i may take `setting` (its parameters in range, nothing newly barely felt). The
  // original setting (all 0) is always allowed.
  virtual bool allowed(std::size_t image, const SeparationSetting& setting) = 0;
  // Felt change of image i at `setting` from its original, JNDs (0 at the original).
  virtual double change_jnd(std::size_t image, const SeparationSetting& setting) = 0;
  // Cue distances between image i at a and image j at b (symmetric).
  virtual CueDistances cues(std::size_t i, const SeparationSetting& a, std::size_t j, const SeparationSetting& b) = 0;
  // Called before a batch of candidates is scored against `state`: a space may compute their
  // features and distances in parallel here. Returns false to stop the search (interrupted).
  virtual bool prepare(const std::vector<SeparationCandidate>& /*batch*/, const std::vector<SeparationSetting>& /*state*/) {
    return true;
  }
  // Whether the exchange phase (3) may go on trying candidates: a space that renders bounds its
  // work here (a budget of variants). The ascent (1) and pruning (2) never ask.
  virtual bool may_explore() { return true; }
};

struct SeparationRequest {
  double target = kIdentifiedTarget;         // every p_ii at least this
  TactileParameterSet vary{};                // the parameters the search may move
  std::vector<bool> keep;                    // per image: stays as it is (empty: none kept)
  std::vector<TactileParameterSet> present;  // per image: the parameters it has (empty: all)
  DiscriminationConstants constants;
  int max_moves = 400;
  // Called after each accepted move (phase 1 ascent, 2 pruning); null: nothing reported.
  std::function<void(int phase, int moves, double shortfall, double change_jnd)> progress;
};

struct SeparationOutcome {
  std::vector<SeparationSetting> settings;  // per image
  std::vector<double> identified;           // p_ii of the proposal
  std::vector<double> change_jnd;           // per image
  double shortfall = 0.0;
  double total_change_jnd = 0.0;            // sum of change_jnd (without the tie-break)
  bool reached = false;                     // shortfall 0
  bool interrupted = false;
  int evaluations = 0;                      // states scored
};

// p_ii of every image of `state`.
std::vector<double> identified_shares(SeparationSpace& space, const std::vector<SeparationSetting>& state,
                                      const DiscriminationConstants& constants);

SeparationOutcome run_separation_search(SeparationSpace& space, const SeparationRequest& request);

// Every state whose settings lie in `choices[i]` (per image), scored exactly: the least change that
// reaches the target, or the least shortfall when none does. For tests on small cases.
SeparationOutcome exhaustive_separation(SeparationSpace& space, const SeparationRequest& request,
                                        const std::vector<std::vector<SeparationSetting>>& choices);

}  // namespace vimg::study
