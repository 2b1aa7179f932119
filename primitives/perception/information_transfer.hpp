#pragma once
// Information transfer of an identification matrix (Miller 1956; Garner & Hake 1951): the mutual
// information, in bits, between the image presented and the image chosen when every image is
// presented equally often,
//   IT = sum_ij (1/n) p(j | i) log2( p(j | i) / q_j ),   q_j = (1/n) sum_i p(j | i),
// with rows presented and columns chosen, each row a distribution (predicted_confusion). A set
// identified perfectly transfers log2 n bits; a set answered at random, 0.
//
// Threads: pure function over caller-owned data.
#include "primitives/perception/perception_matrix.hpp"

namespace vimg {

// The matrix's rows are normalised first (a row of counts works as well as one of shares); rows
// that sum to 0 are left out (never presented). 0 for an empty matrix.
double information_transfer_bits(const PerceptionMatrix& presented_by_chosen);

}  // namespace vimg
