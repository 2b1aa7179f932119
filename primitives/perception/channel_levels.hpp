#pragma once
// The level of a signal through each channel of touch (docs/perception.md, "Level and temporal
// summation"), independent of where in time its content falls:
//   1. the signal filtered by each channel's sensitivity: |H_c(f)|^2 = (displacement of a
//      full-scale component at f / the channel's threshold at f)^2, 0 below kLowestFeltHz; a
//      zero-phase FIR of kChannelFilterTaps (512 ms, Hann-windowed: the frequency resolution of
//      the spectrum frames), applied by overlap-save FFT convolution;
//   2. twice its square: the excitation over time, in threshold units (a steady sine at the
//      channel's threshold reads 1 on average);
//   3. averaged over time as each channel sums it, every 1 ms:
//        Pacinian:     the mean over kPacinianSummationMs (1 s, rectangular): energy summation,
//                      so that the threshold of a burst falls 3 dB per doubling of its duration up
//                      to 1 s and not beyond (Verrillo 1965; Gescheider 1976: summation at high
//                      frequencies, not at low);
//        non-Pacinian: a triangular window kNonPacinianWindowMs (150 ms) wide: no summation
//                      beyond that (Gescheider 1976; Gescheider, Bolanowski & Verrillo 2004). It
//                      averages out the ripple of a squared sine down to kLowestFeltHz, and keeps
//                      the onset of a 25 Hz tone (a 20 ms ramp is half a cycle) from reading
//                      above its steady level (by 0.9 dB at 100 ms, 0.3 dB at 150 ms);
//   4. the level is 10 log10 of the largest value over time.
// A burst is summed whole wherever it falls (the 1 ms grid, not a frame grid, positions the
// windows), so its level does not depend on its position.
//
// Threads: pure; the FFT tables are built once, on first use.
#include <cstddef>
#include <span>

#include "primitives/perception/sensation_level.hpp"

namespace vimg {

inline constexpr double kPacinianSummationMs = 1000.0;   // Verrillo 1965: up to about 1 s
inline constexpr double kNonPacinianWindowMs = 150.0;    // full width of the triangle
inline constexpr std::size_t kChannelFilterTaps = 4096;  // 512 ms at 8 kHz

namespace detail {

struct ChannelLevels {
  double pacinian_db = 0.0;      // may be < 0 (below threshold); kSilentChannelDb for silence
  double non_pacinian_db = 0.0;
  // The Pacinian level summed over `moment_ms` only (channel_levels' argument): the level of the
  // strongest moment on the time scale of the slow envelope.
  double pacinian_moment_db = 0.0;
};

inline constexpr double kSilentChannelDb = -400.0;

ChannelLevels channel_levels(std::span<const double> signal_8khz, const LevelCalibration& calibration, double moment_ms);

}  // namespace detail
}  // namespace vimg
