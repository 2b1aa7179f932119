#pragma once
// Sensation level: how far above the vibrotactile detection threshold a signal is, in dB, per
// octave band (docs/perception.md, "Sensation level"). What ST-SIM leaves out: ST-SIM normalises
// level away, so a texture at full strength and the same texture barely above threshold are the
// same to it.
//   calibration: |x| = 1 is a peak acceleration of full_scale_peak_acceleration_mps2 (the actuator's
//     strength; profiles do not state it, so the default is a documented typical value), and the
//     threshold at its best frequency (250 Hz) is threshold_at_250hz_peak_acceleration_mps2; the
//     shape of the threshold over frequency is vibrotactile_threshold_db() (the ST-SIM curve);
//   per block of 512 samples at 8 kHz (the ST-SIM blocks; a last partial block is zero-padded),
//     per DCT bin k (frequency k * 4000 / 512 Hz) the coefficient in threshold units,
//     X_k * full_scale / T(f_k); per band the level 10 log10(2 / 512 * sum over the band's bins),
//     so that a sine of peak amplitude exactly T(f) reads 0 dB;
//   per signal and band the level of its strongest block (the short-term peak level);
//   "felt" level: the level where above 0 dB, else 0 (below threshold nothing is felt).
//
// Threads: pure functions over caller-owned data.
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace vimg {

struct LevelCalibration {
  // Peak acceleration of the skin contact at |x| = 1. Default 10 m/s^2 (about 1 g): the order of a
  // phone-sized LRA or voice coil at full drive (docs/perception.md). Must be > 0.
  double full_scale_peak_acceleration_mps2 = 10.0;
  // Detection threshold at 250 Hz as peak acceleration: 0.1 um peak displacement (-20 dB re 1 um,
  // Verrillo 1963; Bolanowski et al. 1988) is 0.25 m/s^2 at 250 Hz. Must be > 0.
  double threshold_at_250hz_peak_acceleration_mps2 = 0.25;
};

// Octave bands, centre 250 * 2^i Hz for i = -5..3 (7.8 Hz to 2 kHz), edges at centre / sqrt 2 and
// centre * sqrt 2. The DCT's DC bin belongs to none; nothing above 2.83 kHz is counted.
inline constexpr std::size_t kSensationBands = 9;
inline constexpr std::array<double, kSensationBands> kSensationBandCentresHz = {
    7.8125, 15.625, 31.25, 62.5, 125.0, 250.0, 500.0, 1000.0, 2000.0};

// The level that stands for "no energy at all" in a band (a silent signal), dB.
inline constexpr double kSilentLevelDb = -400.0;

struct SensationLevels {
  // Per band: the level of the strongest block, dB re threshold (negative below threshold;
  // kSilentLevelDb when the band holds no energy in any block).
  std::array<double, kSensationBands> peak_level_db{};
  // Per block (ceil(samples / 512) entries): 1 when some band of that block is above threshold.
  std::vector<std::uint8_t> felt_block;

  // max(peak_level_db[band], 0): what is felt of the band.
  double felt_db(std::size_t band) const;
  // The largest felt_db over the bands (0 when nothing is felt).
  double max_felt_db() const;
};

// signal_8khz: samples at 8 kHz. An empty signal gives kSilentLevelDb everywhere.
SensationLevels sensation_levels(std::span<const double> signal_8khz, const LevelCalibration& calibration = {});

// The detection threshold at frequency_hz as peak acceleration in m/s^2 under `calibration`.
double threshold_peak_acceleration_mps2(double frequency_hz, const LevelCalibration& calibration = {});

}  // namespace vimg
