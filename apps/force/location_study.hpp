#pragma once
// vimg-force --study: the volume paper's location study (section 5) for one participant
// (docs/volume-location-study.md, "Location study"):
//
//   load the study file and plan the participant's trials (study/trial_plan.hpp: the metaphors'
//   order and each trial's data seed); open the device (HID: once; the simulator: afresh in every
//   trial, its hand at the start of its path); open DIR/ID.location.csv (storage/study/trial_log.hpp:
//   a finished participant refused unless --restart; otherwise continue after its last row); then
//   for each remaining trial:
//     1. on a real device, wait with zero force until the participant presses button 0 (or Enter);
//     2. run the haptic loop on the trial's scene (vector guidance plus the one metaphor under test)
//        through the whole safety stack, from the start-up gate and ramp, until button 0 marks;
//     3. stop the loop (zero force at once) and append the trial's row, synced, to the trial file.
//
// The terminal shows "trial n of N, metaphor, elapsed", never the probe's position or the target.
// SIGINT/SIGTERM: the loop stops (zero force first), the trial under way is not written (a trial
// already marked is), exit 130/143. A crash or SIGKILL loses at most the trial under way.
#include <atomic>

#include "apps/force/force_args.hpp"

namespace vimg::force_app {

// Returns the exit status: 0 (every trial done), 1 (bad input, a device fault, a trial file that
// cannot be written), 130 or 143 (a signal).
int run_location_study(const ForceArgs& args, const std::atomic<int>& signal_received);

}  // namespace vimg::force_app
