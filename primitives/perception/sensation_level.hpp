#pragma once
// Sensation level: how far above the vibrotactile detection threshold a signal is, in dB, per
// octave band (docs/perception.md, "Sensation level"). What ST-SIM leaves out: ST-SIM normalises
// level away, so a texture at full strength and the same texture barely above threshold are the
// same to it.
//   threshold:   the detection threshold as peak skin displacement, U-shaped over frequency: the
//     shape of vibrotactile_threshold_db() (the ST-SIM curve: lowest at 250 Hz, 39 dB higher at
//     40 Hz, 55 dB at 10 Hz), anchored at 250 Hz to threshold_at_250hz_peak_displacement_m;
//   calibration: the signal is acceleration; |x| = 1 is full_scale_peak_acceleration_mps2 (the
//     actuator's strength: profiles do not state it, so the default is a documented typical value);
//     a component at f moves the skin by acceleration / (2 pi f)^2;
//   per frame of 512 samples at 8 kHz under a periodic Hann window, frames 256 samples apart
//     (centred on every ST-SIM block's start and middle; zeros outside the signal), per DCT bin k
//     (frequency k * 4000 / 512 Hz) the coefficient in threshold units,
//     X_k * full_scale / (2 pi f_k)^2 / threshold(f_k); per band the level
//     10 log10(2 / (512 * 3/8) * sum over the band's bins of its square), so that a steady sine
//     whose peak displacement is exactly the threshold reads 0 dB (the window keeps a component's
//     energy near its own frequency, where the threshold is its own);
//   per signal and band the level of its strongest frame (the short-term peak level);
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
  // Detection threshold at 250 Hz as peak displacement: 0.1 um (-20 dB re 1 um; Verrillo 1963,
  // Bolanowski et al. 1988). Must be > 0.
  double threshold_at_250hz_peak_displacement_m = 1e-7;
};

// Bands: everything from 5.5 Hz up to 44 Hz in one (the 64 ms frames resolve about 16 Hz, too
// coarse for octaves down there), then octaves centred on 62.5 * 2^i Hz up to 2 kHz, edges at
// centre / sqrt 2 and centre * sqrt 2. The DCT's DC bin belongs to none; nothing above 2.83 kHz
// is counted. kSensationBandLowHz[b] and kSensationBandHighHz[b]: band b is [low, high).
inline constexpr std::size_t kSensationBands = 7;
inline constexpr std::array<double, kSensationBands> kSensationBandLowHz = {
    5.524271728019903, 44.19417382415922, 88.38834764831844, 176.7766952966369,
    353.5533905932738, 707.1067811865476, 1414.213562373095};
inline constexpr std::array<double, kSensationBands> kSensationBandHighHz = {
    44.19417382415922, 88.38834764831844, 176.7766952966369, 353.5533905932738,
    707.1067811865476, 1414.213562373095, 2828.42712474619};

// The level that stands for "no energy at all" in a band (a silent signal), dB.
inline constexpr double kSilentLevelDb = -400.0;

struct SensationLevels {
  // Per band: the level of the strongest block, dB re threshold (negative below threshold;
  // kSilentLevelDb when the band holds no energy in any block).
  std::array<double, kSensationBands> peak_level_db{};
  // Per ST-SIM block (ceil(samples / 512) entries): 1 when some band of a frame overlapping the
  // block is above threshold and the block is not all zeros.
  std::vector<std::uint8_t> felt_block;

  // max(peak_level_db[band], 0): what is felt of the band.
  double felt_db(std::size_t band) const;
  // The largest felt_db over the bands (0 when nothing is felt).
  double max_felt_db() const;
};

// signal_8khz: samples at 8 kHz. An empty signal gives kSilentLevelDb everywhere.
SensationLevels sensation_levels(std::span<const double> signal_8khz, const LevelCalibration& calibration = {});

// The detection threshold at frequency_hz as peak displacement in m under `calibration`.
double threshold_peak_displacement_m(double frequency_hz, const LevelCalibration& calibration = {});

}  // namespace vimg
