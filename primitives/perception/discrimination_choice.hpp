#pragma once
// From cue distances to predicted confusion (docs/perception.md, "Choice"): the cues of a pair
// (discrimination_cues.hpp, in JNDs) combine as a Euclidean distance, and a Shepard (1957) - Luce
// (1959) choice rule with a lapse rate turns the distances of a set into the confusion matrix:
//   D_ij = sqrt(sum_c (w_c d_ij,c)^2)                                   (combined_distance_jnd)
//   p(j | i) = (1 - lapse) exp(-D_ij / T) / sum_k exp(-D_ik / T) + lapse / n   (rows sum to 1)
// rows presented, columns chosen, n the size of the set. With the default T = 1 / ln 3 a pair one
// JND apart, alone, is confused exp(-ln 3) / (1 + exp(-ln 3)) = 25 % of the time (the 75 % point
// of a two-alternative discrimination: a JND's usual definition); identical signals split their
// rows evenly.
//
// Threads: pure functions over caller-owned data.
#include <array>
#include <cmath>
#include <limits>

#include "primitives/perception/discrimination_cues.hpp"
#include "primitives/perception/perception_matrix.hpp"

namespace vimg {

struct DiscriminationConstants {
  double temperature_jnd = 1.0 / std::log(3.0);  // alone, a pair one JND apart is confused 25 % of the time
  double lapse_rate = 0.0;                       // share of answers that are guesses, uniform over the set
  std::array<double, kCueCount> cue_weight = [] {  // per cue, 1 each: a JND weighs one JND
    std::array<double, kCueCount> w{};
    w.fill(1.0);
    return w;
  }();
};

// sqrt(sum_c (w_c d_c)^2); negative or NaN distances and weights count as 0.
double combined_distance_jnd(const CueDistances& d, const DiscriminationConstants& k = {});

// A temperature is > 0 and finite. Where constants are read they are checked, with an error that
// says so (MODEL.json and a compare report's model: storage/study/perception_model_file.hpp).
constexpr bool valid_temperature_jnd(double t) { return t > 0.0 && t < std::numeric_limits<double>::infinity(); }

// d: square [presented][chosen]. With an invalid temperature (valid_temperature_jnd) every cell is
// NaN: no default stands in for it. The lapse rate is clamped to [0, 1]. Returns the confusion matrix
// (empty for an empty input).
PerceptionMatrix discrimination_confusion(const CueMatrix& d, const DiscriminationConstants& k = {});

// The confusion of two signals alone, `distance_jnd` apart: a row of the 2 x 2 matrix.
double two_alternative_confusion(double distance_jnd, const DiscriminationConstants& k = {});

}  // namespace vimg
