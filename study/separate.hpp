#pragma once
// `vimg separate` and the editor's "Propose changes" (docs/separate.md): the smallest change of a
// set's tactile parameters that lets people identify every image at least `target` of the time.
//
// 1. The set is compared exactly as `vimg compare` compares it (run_compare: the same exploration,
//    actuator, perception model and constants); its per-image features are kept and reused.
// 2. When every image is identified at least `target` of the time, nothing is proposed.
// 3. Otherwise the search of separate_search.hpp moves the tactile parameters of
//    separate_space.hpp. Each variant of an image is rendered and analysed once (the same render
//    and analysis as run_compare), on every core, and each pair's cue distances once: a pair whose
//    images did not change is never recomputed.
// 4. A proposal never leaves the format's ranges (separate_space.hpp) and never makes a primitive
//    barely felt on the actuator that was felt in the original (weak_primitives: the same check as
//    `vimg validate --actuator`).
//
// Threads: run_separate() blocks its caller and renders on `threads` threads; it may run on any
// thread that is not a real-time one (the editor runs it on a worker thread).
#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "primitives/image.hpp"
#include "study/compare.hpp"
#include "study/separate_search.hpp"
#include "study/separate_space.hpp"

namespace vimg::study {

// The search's budget: its exchange phase (separate_search.hpp) stops once this many variants per
// image have been rendered (a render of the standard exploration of a 60 x 110 mm canvas and its
// analysis take about 0.1 s of one core; docs/benchmarks/perception-compare-separate.md, "vimg separate").
inline constexpr int kSearchVariantsPerImage = 48;

struct SeparateRequest {
  std::vector<std::filesystem::path> inputs;  // images (.vimg, .png); rendered signals cannot be changed
  CompareActuator actuator;
  std::vector<CompareGesture> gestures;       // empty: the standard exploration
  ExplorationSpec exploration;
  LevelCalibration calibration;
  DiscriminationConstants discrimination;
  double target = kIdentifiedTarget;          // in (0, 1)
  TactileParameterSet vary = all_tactile_parameters();
  std::vector<bool> keep;                     // per input: stays as it is (empty: none)
  // The indices (paint order, as primitive_frequencies walks them) of the image's primitives the
  // actuator barely renders; null: none (the ideal actuator).
  std::function<std::vector<std::size_t>(const Image&)> weak_primitives;
  std::string felt_band;                      // the actuator's band for the limits ("151-203 Hz"); "" if none
  int threads = 0;                            // <= 0: one per core
  bool (*should_stop)() = nullptr;
  // A line of progress ("move 3: 2 images below target, change 1.8 JNDs, 54 variants rendered").
  std::function<void(const std::string&)> progress;
};

struct SeparateImage {
  std::string path, label;
  Image original, proposal;
  std::vector<ParameterChange> changes;
  SeparationSetting setting{};
  double change_jnd = 0.0;
  double identified_before = 0.0, identified_after = 0.0;
  bool kept = false;
};

struct SeparateResult {
  CompareResult before;                   // vimg compare's result on the designer's set
  std::vector<SeparateImage> images;
  PerceptionMatrix confusion_after;       // rows presented, columns chosen
  CueMatrix cues_after;
  double information_before_bits = 0.0, information_after_bits = 0.0;
  double target = kIdentifiedTarget;
  TactileParameterSet vary{};
  bool already_distinct = false;          // every image already at the target: nothing proposed
  bool reached = false;                   // the proposal meets the target
  std::vector<std::string> limits;        // when not reached: what limits it
  int variants_rendered = 0;
  int states_scored = 0;
  std::vector<Diagnostic> diagnostics;    // errors: nothing else is set
  bool interrupted = false;
  bool ok() const { return !interrupted && !has_errors(diagnostics) && before.ok(); }
  double total_change_jnd() const;
};

SeparateResult run_separate(const SeparateRequest& request);

}  // namespace vimg::study
