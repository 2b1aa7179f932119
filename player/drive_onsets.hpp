#pragma once
// Where a rendered drive starts to be felt: the onsets of its bursts, for measuring how far a
// felt edge lies from where it is drawn (docs/latency.md, bench/touch_prediction_bench.cpp).
// An onset is the first sample whose magnitude exceeds threshold after at least quiet_s of
// samples at or below it (the signal's start counts as quiet).
#include <span>
#include <vector>

namespace vimg {

std::vector<double> drive_onsets_s(std::span<const float> drive, double rate_hz, double start_time_s,
                                   double threshold = 0.01, double quiet_s = 0.03);

// The felt onset error of a render against the exact one: for each onset of `exact`, the nearest
// onset of `felt`, |difference| x the finger's speed there (the caller's speed_mm_per_s); the
// mean, in mm. NaN when `exact` has no onset or `felt` has none.
double mean_onset_error_mm(const std::vector<double>& exact_onsets_s, const std::vector<double>& felt_onsets_s,
                           double speed_mm_per_s);

}  // namespace vimg
