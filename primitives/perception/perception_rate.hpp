#pragma once
// The rate of every signal the perception model analyses (analyse_discrimination, channel_levels,
// analyse_stsim): 8 kHz. ST-SIM is defined at it by its reference implementation (stsim.hpp holds
// its own constant and checks that the two agree), and `vimg compare` renders and reads signals at
// it (storage/signal_file.hpp, kCompareRateHz).
namespace vimg {

inline constexpr double kPerceptionRateHz = 8000.0;

}  // namespace vimg
