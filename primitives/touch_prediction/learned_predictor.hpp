#pragma once
// The `learned` model of the touch predictor (finger_predictor.hpp): a small fixed-weight network
// trained on real finger traces (learned_weights.hpp, made by scripts/train_touch_predictor.py;
// docs/touch-prediction.md, "The learned model"). Pure: no allocation, no clock, O(1) per
// prediction (at most kHistoryCapacity points are looked at, then one forward pass of about 2 k
// multiply-adds).
//
// Inputs, from the caller's FingerHistory (its newest point p_0 at t_n):
//   - the newest kLearnedPoints points at least kLearnedMinStep_s apart (the newest, then walking
//     back), padded with the oldest at kLearnedNominalGap_s gaps (the finger was put down there);
//   - their steps (newest first) in the stroke's frame: rotated so that p_0 - p_3 points along +x,
//     divided by S, the steps' mean length; each step's time gap in nominal gaps (minus 1,
//     clipped to [-1, 3]);
//   - the horizon, min(h, kLearnedHorizonRef_s) / kLearnedHorizonRef_s, and ln(S / 1 mm) / 2
//     clipped to [-3, 2].
// Two ReLU layers and a tanh output f (two values) give the network's offset from p_0, in the
// stroke frame,  o_net = S * (h / kLearnedHorizonRef_s) * kLearnedMaxGain * tanh(...),  rotated back.
// A gate blends it with the newest step's velocity v_1 (step / gap):
//   offset = g v_1 h + (1 - g) o_net,  g = exp(-rho / kLearnedGateScale),
// rho the rms of |v_j - v_1| / |v_1| over the older steps j (g = 0 when v_1 = 0). Guarantees by
// construction (tests/touch_prediction/learned_predictor_test.cpp):
//   - a still finger (every step zero, S = 0) is predicted exactly where it is; h = 0 gives p_0;
//   - a constant velocity (rho = 0, g = 1), at any event rate and timing, is continued exactly;
//   - |o_net| <= sqrt(2) kLearnedMaxGain S h / kLearnedHorizonRef_s, and g is small unless every
//     step has nearly v_1: the offset is at most a fixed multiple of the recent steps' lengths, so
//     no offset runs away on stop-and-go or jittered input;
//   - the offset is clamped to h kLearnedReachPerSecond D, D the largest distance from p_0 to the
//     points back to the newest one at least kLearnedRecent_s old: a finger that has rested
//     kLearnedRecent_s is predicted exactly where it is (the bound every model keeps,
//     tests/touch_prediction/no_runaway_test.cpp);
//   - the same history rotated, mirrored across its direction of motion, or moved gives the same
//     prediction rotated, mirrored or moved (to rounding).
#include <array>

#include "primitives/touch_prediction/finger_predictor.hpp"

namespace vimg {

// The position at the last event's time + horizon_s (>= 0, finite) from a non-empty history.
PredictedPosition predict_learned(const FingerHistory& history, double horizon_s);

// The same at two horizons, each exactly as predict_learned() gives it, for about 1.5 times the
// cost of one: the inputs, the gate, the reach and the first layer's sums over the steps are the
// history's, shared (predicted_path.hpp predicts a span's two ends at once).
std::array<PredictedPosition, 2> predict_learned_pair(const FingerHistory& history, double first_horizon_s,
                                                      double second_horizon_s);

}  // namespace vimg
