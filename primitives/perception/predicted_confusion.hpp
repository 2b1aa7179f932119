#pragma once
// Predicted confusion of a set of signals from their perceptual similarity (docs/perception.md):
// Shepard's (1957) and Luce's (1959) choice model with equal response biases,
//   p(j | i) = exp(-d_ij / tau) / sum_k exp(-d_ik / tau),  d = 1 - similarity,
// rows presented, columns chosen, each row summing to 1. Two identical signals split their rows
// evenly between them. A pair is likely confused when p(j | i) or p(i | j) reaches
// likely_confused_p (0.2: one of the paper's five repetitions per image).
//
// Threads: pure functions over caller-owned data.
#include <cstddef>
#include <vector>

#include "primitives/perception/perceptual_similarity.hpp"

namespace vimg {

struct ChoiceModel {
  double tau = 0.1;                 // distance scale; one not > 0 counts as 0.1
  double likely_confused_p = 0.2;   // threshold for the warning
};

// similarity: square, entries in [0, 1] (values outside are clamped, NaN counts as 0). Returns the
// confusion matrix of the same size (empty for an empty input).
PerceptionMatrix predicted_confusion(const PerceptionMatrix& similarity, const ChoiceModel& model = {});

struct ConfusedPair {
  std::size_t a = 0;  // a < b
  std::size_t b = 0;
  double p = 0.0;     // max(p(b | a), p(a | b))
};

// Pairs with p >= model.likely_confused_p, most confused first (ties by a, then b).
std::vector<ConfusedPair> likely_confused_pairs(const PerceptionMatrix& confusion, const ChoiceModel& model = {});

}  // namespace vimg
