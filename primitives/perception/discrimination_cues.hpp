#pragma once
// What a person can tell apart between two vibrations, cue by cue, in just-noticeable differences
// (docs/perception.md, "Discrimination model"). Analyse each signal once, then measure the distance
// of every pair on each cue; discrimination_choice.hpp turns the distances into predicted confusion.
//
// The signal is the acceleration at the skin (|x| = 1 is LevelCalibration::full_scale, 8 kHz).
// Two channels of touch (Bolanowski, Gescheider, Verrillo & Checkosky 1988):
//   Pacinian (P):      detection threshold as peak displacement, U-shaped over frequency, lowest at
//                      250 Hz (threshold_peak_displacement_m of sensation_level.hpp, 0.1 um there);
//   non-Pacinian (NP): flat in displacement, kNonPacinianThresholdPeakDisplacementM, the floor of
//                      the threshold below about 40 Hz.
// A component of acceleration A at f moves the skin by A / (2 pi f)^2; divided by a channel's
// threshold it is that channel's excitation in threshold units, and the skin feels through the
// more sensitive channel: excitation = max(P, NP) per frequency, sensation level 10 log10 of it.
//
// Features of one signal:
//   spectrum:  frames of kSpectrumFrameSamples (512 ms) under a Hann window, half a frame apart;
//              per FFT bin the excitation (threshold units, scaled so that a steady sine at the
//              threshold sums to 1 over its bins);
//   level_db:  the sensation level of the strongest spectrum frame (0 when nothing is felt): the
//              level of a steady vibration; a burst shorter than the frame's ~190 ms effective
//              length reads lower by 10 log10(duration / 190 ms), the temporal summation of the
//              Pacinian channel (Verrillo 1965: about 3 dB per doubling of duration);
//   pitch:     log2 of the excitation-weighted mean log-frequency (the centroid, in octaves, of the
//              frame-averaged excitation): a sine's own frequency; a texture's dominant one;
//   envelope:  every kEnvelopeStepSamples (1 ms) the power of the signal around it under a Hann
//              window kEnvelopeWindowMs wide (fast: the skin's temporal resolution, which sets gap
//              detection) and that power smoothed again over kSlowEnvelopeWindowMs (slow: brief
//              increments sum over time, as the Pacinian channel's threshold does), in dB relative
//              to the slow envelope's largest value, floored at -level_db (below threshold nothing is
//              felt, so a gap in a faint vibration is shallower than in a strong one). Kept: the slow
//              envelope (level over time) and the dips: how far the fast
//              envelope falls below the smaller of its largest values within kDipContextMs before
//              and after (a gap has signal on both sides; an onset or an end does not); and the
//              rhythm: the same against the smaller of its means over kRhythmContextMs before and
//              after (the silences between bursts, too long for the dips' context and smoothed away
//              by the slow envelope; a mean, so that a brief click beside a silence counts little);
//              where the signal falls silent, the depth it would have there is kept with it;
//
// Cue distances between two signals a and b, each >= 0, in JNDs, symmetric, 0 for identical:
//   level:    |level_a - level_b| / kLevelJndDb;
//   pitch:    |pitch_a - pitch_b| / log2(1 + kFrequencyWeberFraction), scaled by
//             min(1, min(level_a, level_b) / kFullSalienceLevelDb): pitch needs both to be felt;
//   envelope: the largest difference, in dB, of the two slow envelopes, dip or rhythm tracks
//             (rhythm: silences in both are alike, however loud around them),
//             each moment against the other's range within +-kTimingToleranceMs (free exploration
//             does not repeat its timing exactly), scaled by min(1, felt level there /
//             kFullSalienceLevelDb) (the stronger of the two), / kLevelJndDb: a gap, a rhythm.
//
// Threads: pure functions over caller-owned data.
#include <array>
#include <cstddef>
#include <span>
#include <string_view>
#include <vector>

#include "primitives/perception/sensation_level.hpp"

namespace vimg {

// Published figures behind the cues (tests/data/psychophysics/published_figures.csv).
inline constexpr double kLevelJndDb = 2.0;               // amplitude JND: 1.65-2.98 dB (Israr, Tan & Reed 2006)
inline constexpr double kFrequencyWeberFraction = 0.25;  // 0.13-0.38 (Israr et al. 2006), 0.2-0.35 (Goff 1967)
inline constexpr double kNonPacinianThresholdPeakDisplacementM = 10e-6;  // NP floor below ~40 Hz
// Reasoned constants (docs/perception.md says why).
// Differences of pitch and envelope count fully from this sensation level, less below it (in
// proportion): near threshold a vibration is felt as little more than "something".
inline constexpr double kFullSalienceLevelDb = 10.0;
inline constexpr double kEnvelopeWindowMs = 40.0;  // the fast envelope's window (Hann, full width): gaps
inline constexpr double kSlowEnvelopeWindowMs = 400.0;  // the slow envelope's (Hann): summation of increments
inline constexpr double kDipContextMs = 50.0;  // a dip is measured against the envelope this far on both sides
// A rhythm's gap is measured against the means this far on both sides: the slow envelope's
// half-width, so that gaps it smooths away are seen (not a constant of its own).
inline constexpr double kRhythmContextMs = kSlowEnvelopeWindowMs / 2.0;
inline constexpr double kTimingToleranceMs = 20.0;  // timing shifts that go unnoticed
inline constexpr double kLowestFeltHz = 10.0;  // below: drift of the acceleration signal, not counted
inline constexpr std::size_t kSpectrumFrameSamples = 4096;
inline constexpr std::size_t kEnvelopeStepSamples = 8;

// A track over time, one value per kEnvelopeStepSamples (1 ms), dB.
struct EnvelopeTrack {
  std::vector<float> db;
  std::vector<float> low_db;   // the least of db within +-kTimingToleranceMs of each step
  std::vector<float> high_db;  // the largest
  float silent_db = 0.0f;      // its value in silence (before and after the signal)
  // Rhythm only: the depth its gap would have if the signal fell silent there (-(felt level of
  // what surrounds it)): two gaps down to silence are alike however loud their surroundings, which
  // the level cue tells apart. Empty for the other tracks.
  std::vector<float> silence_db;
};

struct DiscriminationFeatures {
  double level_db = 0.0;                 // felt sensation level of the strongest moment, >= 0
  double moment_level_db = 0.0;          // the same summed over kSlowEnvelopeWindowMs only: the envelope's scale
  double pacinian_level_db = 0.0;        // the same through the P channel alone (may be < 0)
  double non_pacinian_level_db = 0.0;    // through the NP channel alone (may be < 0)
  double pitch_octaves = 0.0;            // log2 of the centroid frequency in Hz (0 when nothing is felt)
  EnvelopeTrack slow_envelope;           // dB re its strongest moment, >= -level_db (silence)
  EnvelopeTrack dips;                    // dB <= 0: how far the fast envelope falls below its surroundings
  EnvelopeTrack rhythm;                  // dB <= 0: the same against the means over kRhythmContextMs
};

DiscriminationFeatures analyse_discrimination(std::span<const double> signal_8khz,
                                              const LevelCalibration& calibration = {});

inline constexpr std::size_t kCueCount = 3;
enum class Cue : std::size_t { level = 0, pitch = 1, envelope = 2 };

// "level", "pitch", "envelope"; "" for cue >= kCueCount.
std::string_view cue_name(std::size_t cue);

using CueDistances = std::array<double, kCueCount>;

CueDistances cue_distances(const DiscriminationFeatures& a, const DiscriminationFeatures& b);

// [presented][chosen]: cue_distances of every pair; square, zeros on the diagonal, symmetric.
using CueMatrix = std::vector<std::vector<CueDistances>>;
CueMatrix cue_matrix(std::span<const DiscriminationFeatures> signals);
// cue_matrix in parts, for callers that spread the rows over threads (study/compare.cpp): row i
// of the upper triangle (m[i][j] for j > i; m square, n x n), then the lower triangle mirrored.
// Different rows touch different elements, so rows may be filled at once.
void fill_cue_matrix_row(std::span<const DiscriminationFeatures> signals, std::size_t i, CueMatrix& m);
void mirror_cue_matrix(CueMatrix& m);

// The detection threshold of the skin (the more sensitive channel) at frequency_hz, as peak
// displacement in m.
double skin_threshold_peak_displacement_m(double frequency_hz, const LevelCalibration& calibration = {});

}  // namespace vimg
