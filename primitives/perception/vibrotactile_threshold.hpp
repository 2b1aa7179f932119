#pragma once
// The vibrotactile detection threshold curve ST-SIM subtracts from its block spectra: the U-shaped
// curve of the `vibromaf` reference implementation (vibromaf/signal/perception.py, the perceptual
// model of Hassen and Steinbach's vibrotactile codecs; docs/perception.md):
//   T(f) = |62 / log10(c)^2 * log10(f / 550 + c)^2| - 77 dB,  c = 1 - 250 / 550,
// lowest at 250 Hz (-77 dB), 62 dB higher at 0 Hz, rising steeply below 100 Hz and above 250 Hz
// until it reaches 0 dB (near 781 Hz), where the reference holds it constant. dB re a DCT
// coefficient of 1 (the ST-SIM domain), i.e. relative. The discrimination model's Pacinian
// threshold (sensation_level.hpp) follows its rise above 250 Hz only; below, it has the published
// slope.
#include <array>
#include <cstddef>

#include "primitives/perception/stsim.hpp"

namespace vimg {

inline constexpr double kThresholdBestFrequencyHz = 250.0;
inline constexpr double kThresholdAtBestFrequencyDb = -77.0;

// The curve at frequency_hz >= 0, held at 0 dB from where it first reaches 0 dB (the continuous
// form; the reference holds its first positive sample, see below).
double vibrotactile_threshold_db(double frequency_hz);

// The curve sampled exactly as the reference samples it for a 512-sample block: DCT bin k at
// k * 8000 / 1023 Hz (numpy's linspace(0, fs, 1024)[:512]), and from the first bin above 0 dB on,
// that bin's value.
const std::array<double, kStSimBlockSamples>& stsim_threshold_db_per_bin();

}  // namespace vimg
