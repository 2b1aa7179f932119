#pragma once
// A square matrix of per-pair values over a set of signals, rows and columns in the order of the
// signals (similarities, ST-SIM, predicted confusion: rows presented, columns chosen).
#include <vector>

namespace vimg {

using PerceptionMatrix = std::vector<std::vector<double>>;

}  // namespace vimg
