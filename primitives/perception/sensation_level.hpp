#pragma once
// The calibration from a signal to the skin (docs/perception.md, "Discrimination model"): the
// signal is acceleration, |x| = 1 being LevelCalibration::full_scale_peak_acceleration_mps2; a
// component at f moves the skin by acceleration / (2 pi f)^2, and the Pacinian detection threshold
// as peak displacement is U-shaped over frequency, anchored at 250 Hz to
// threshold_at_250hz_peak_displacement_m:
//   below 250 Hz it rises kPacinianSlopeBelowBestDbPerOctave = 13 dB per octave: the published
//     12 dB/octave (Verrillo 1963, large contactor; read 10-14), the least whole slope that also
//     meets the published floor of 5 um or more at 40 Hz;
//   above 250 Hz it rises as the ST-SIM curve does (vibrotactile_threshold_db(): +24 dB at 500 Hz,
//     +77 dB from 781 Hz), for which no published figure is in the conformance data.
// Below kLowestModelledThresholdHz (and for a frequency that is not a number) it is its value there.
// Sensation level is 20 log10 of the displacement over the threshold.
//
// Threads: pure functions.

namespace vimg {

inline constexpr double kPacinianSlopeBelowBestDbPerOctave = 13.0;
inline constexpr double kLowestModelledThresholdHz = 1.0;

struct LevelCalibration {
  // Peak acceleration of the skin contact at |x| = 1. Default 10 m/s^2 (about 1 g): the order of a
  // phone-sized LRA or voice coil at full drive (docs/perception.md). Must be > 0.
  double full_scale_peak_acceleration_mps2 = 10.0;
  // Detection threshold at 250 Hz as peak displacement: 0.1 um (-20 dB re 1 um; Verrillo 1963,
  // Bolanowski et al. 1988). Must be > 0.
  double threshold_at_250hz_peak_displacement_m = 1e-7;
};

// The Pacinian detection threshold at frequency_hz as peak displacement in m under `calibration`.
double threshold_peak_displacement_m(double frequency_hz, const LevelCalibration& calibration = {});

}  // namespace vimg
