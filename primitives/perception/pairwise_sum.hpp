#pragma once
// A sum in exactly NumPy's order (numpy/core/src/umath/loops_utils.h.src, pairwise_sum): under 8
// terms one after another; up to 128 terms in eight running sums combined as
// ((r0 + r1) + (r2 + r3)) + ((r4 + r5) + (r6 + r7)) and then the rest; longer runs split in two at
// half the length rounded down to a multiple of 8. ST-SIM matches its reference implementation
// only with the same rounding: a constant block's mean is not always the constant in floating
// point, and the reference normalises that difference by (deviation + eps).
// term(i) gives the i-th term; it is called once per term.
#include <cstddef>

namespace vimg::detail {

template <class Term>
double pairwise_sum(std::size_t first, std::size_t count, const Term& term) {
  if (count < 8) {
    double sum = 0.0;
    for (std::size_t i = 0; i < count; ++i) sum += term(first + i);
    return sum;
  }
  if (count <= 128) {
    double r[8];
    for (std::size_t j = 0; j < 8; ++j) r[j] = term(first + j);
    std::size_t i = 8;
    for (; i < count - (count % 8); i += 8) {
      for (std::size_t j = 0; j < 8; ++j) r[j] += term(first + i + j);
    }
    double sum = ((r[0] + r[1]) + (r[2] + r[3])) + ((r[4] + r[5]) + (r[6] + r[7]));
    for (; i < count; ++i) sum += term(first + i);
    return sum;
  }
  std::size_t half = count / 2;
  half -= half % 8;
  return pairwise_sum(first, half, term) + pairwise_sum(first + half, count - half, term);
}

// NumPy's np.sum of `count` terms: the identity 0 plus the pairwise sum.
template <class Term>
double numpy_sum(std::size_t count, const Term& term) {
  return 0.0 + pairwise_sum(0, count, term);
}

}  // namespace vimg::detail
