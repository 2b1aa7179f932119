#pragma once
// `vimg compare` and the editor's prediction (docs/studies.md, "Predicting confusion: vimg
// compare"): will people tell these images apart? Every image is rendered under the same gestures
// (the standard exploration of study/exploration.hpp for the images' canvas, or the gestures given)
// through the actuator's model (compare_render.hpp); a rendered signal (WAV or render CSV,
// compare_signal.hpp) is taken as it is. Then the discrimination model of primitives/perception
// (docs/perception.md): every input's cues (level, pitch, envelope), their distances in JNDs for
// every pair, the predicted confusion of the choice rule, and the pairs likely confused; beside it,
// ST-SIM of every ordered pair as the reference implementation computes it (reported, not used for
// the confusion).
//
// Threads: run_compare() renders and analyses the images on `threads` threads at once
// (storage/parallel_tasks.hpp) and blocks until all is done; it may run on any thread that is not a
// real-time one (the editor runs it on a worker thread).
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "primitives/gesture.hpp"
#include "primitives/actuator/response_params.hpp"
#include "primitives/perception/discrimination_choice.hpp"
#include "primitives/perception/identification_choice.hpp"
#include "primitives/perception/discrimination_cues.hpp"
#include "primitives/perception/predicted_confusion.hpp"
#include "primitives/perception/sensation_level.hpp"
#include "primitives/perception/stsim.hpp"
#include "storage/diagnostic.hpp"
#include "study/exploration.hpp"

namespace vimg::study {

// The actuator the images are felt through (`--actuator P`; the ideal one by default).
struct CompareActuator {
  std::string name = "ideal";  // the profile's name
  std::string file;            // the profile file as given; empty for the built-in ideal actuator
  ResponseParams response;     // its response model (the ideal one gives the drive itself)
};

struct CompareGesture {
  std::string file;  // as given (for reports)
  Gesture gesture;
};

struct CompareRequest {
  std::vector<std::filesystem::path> inputs;  // images (.vimg, .png) and rendered signals (.wav, .csv)
  CompareActuator actuator;
  std::vector<CompareGesture> gestures;  // empty: the standard exploration of the images' canvas
  ExplorationSpec exploration;
  LevelCalibration calibration;
  // The discrimination model's free constants (docs/perception.md): the confusion comes from them.
  DiscriminationConstants discrimination;
  ChoiceModel choice;                    // likely_confused_p: the warning's threshold
  bool stsim = true;                     // ST-SIM of every pair (reported, never predicted from); false: `stsim` stays empty
  int threads = 0;                       // <= 0: one per core
  bool (*should_stop)() = nullptr;       // asked between render blocks (SIGINT); null: never
  // Called once per input when its signal is analysed (`analysed` of `total`), from the worker
  // threads, one call at a time; null: nothing is reported.
  void (*progress)(std::size_t analysed, std::size_t total) = nullptr;
};

enum class CompareInputKind { image, wav_signal, csv_signal };

struct CompareInput {
  std::string path;   // as given
  std::string label;  // its file name (the path as given when two inputs share a file name)
  CompareInputKind kind = CompareInputKind::image;
  double duration_s = 0.0;  // of its signal (rendered or read), at 8 kHz
};

struct CompareResult {
  std::vector<CompareInput> inputs;
  std::optional<double> canvas_width_mm, canvas_height_mm;  // the images' common canvas, if any image
  std::optional<Exploration> exploration;                   // when the standard exploration was used
  std::vector<std::string> gesture_files;                   // when gestures were given
  CompareActuator actuator;
  LevelCalibration calibration;
  ChoiceModel choice;
  DiscriminationConstants discrimination;            // as requested
  // stsim[i][j]: ST-SIM of input i against reference j over their common length, exactly as the
  // reference implementation (vibromaf) computes it (stsim_matrix): a codec-distortion metric,
  // reported beside the prediction, not part of it. Up to 7.6e8 against a reference that is, in
  // some block, only a decayed ring (docs/stsim.md, "Values far above 1"); NaN: no value.
  PerceptionMatrix stsim;
  std::vector<DiscriminationFeatures> features;      // of every input, in order
  CueMatrix cues;                                    // cue_matrix(features): [presented][chosen], JNDs
  PerceptionMatrix distance_jnd;                     // combined_distance_jnd of cues under discrimination
  PerceptionMatrix predicted_confusion;  // identification_confusion: rows presented, columns chosen, each sums to 1
  std::vector<ConfusedPair> likely_confused;
  std::vector<std::string> warnings;     // "A.vimg ~ B.vimg: likely confused (p = 0.50)", one per pair
  std::vector<Diagnostic> diagnostics;   // of the inputs (warnings, or errors: then nothing else is set)
  bool interrupted = false;              // should_stop() said so; nothing else is set
  bool ok() const { return !interrupted && !has_errors(diagnostics) && !predicted_confusion.empty(); }
};

// What an input is, by its extension: .wav and .csv are rendered signals, anything else an image.
CompareInputKind compare_input_kind(const std::filesystem::path& path);

// The warning for one likely confused pair: "A.vimg ~ B.vimg: likely confused (p = 0.50)".
std::string confusion_warning(const std::string& label_a, const std::string& label_b, double p);

// The warning for an image identified less than kIdentifiedTarget (`vimg separate`'s default
// target) of the time though no image is likely confused with it (its confusions are spread, or
// each below likely_confused_p): "B.vimg: identified 69 % of the time (below 90 %), most often
// taken for A.vimg (p = 0.15)". One per such image, after the pairs' warnings; an image in a likely
// confused pair has its warning already.
std::vector<std::string> poorly_identified_warnings(const PerceptionMatrix& confusion, const std::vector<ConfusedPair>& pairs,
                                                    const std::vector<std::string>& labels);

// The whole comparison. Errors (an input that does not load, images of different canvas sizes, a
// canvas too large for the standard exploration, fewer than 2 or more than kMaxCompareInputs
// inputs) come back as diagnostics; the caller prints them.
CompareResult run_compare(const CompareRequest& request);

}  // namespace vimg::study
