#pragma once
// The pairs of a predicted confusion matrix (rows presented, columns chosen; discrimination_choice.hpp
// computes it) a designer is warned about: a pair is likely confused when p(j | i) or p(i | j)
// reaches likely_confused_p (0.2: one of the paper's five repetitions per image).
//
// Threads: pure functions over caller-owned data.
#include <cstddef>
#include <vector>

#include "primitives/perception/perception_matrix.hpp"

namespace vimg {

struct ChoiceModel {
  double likely_confused_p = 0.2;   // threshold for the warning
};

struct ConfusedPair {
  std::size_t a = 0;  // a < b
  std::size_t b = 0;
  double p = 0.0;     // max(p(b | a), p(a | b))
};

// Pairs with p >= model.likely_confused_p, most confused first (ties by a, then b).
std::vector<ConfusedPair> likely_confused_pairs(const PerceptionMatrix& confusion, const ChoiceModel& model = {});

}  // namespace vimg
