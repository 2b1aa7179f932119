#pragma once
// MODEL.json: the constants of the identification model that `vimg study fit` wrote and
// `vimg compare --model` and `vimg separate --model` read (docs/format-model.md A9). Versioned JSON:
//
//   {
//     "format": "vimg-perception-model",
//     "version": 1,
//     "constants": {"temperature_jnd": 0.91, "lapse_rate": 0.04,
//                   "cue_weight": {"level": 1.3, "pitch": 0.7, "envelope": 1}},
//     "fitted": ["lapse_rate", "cue_weight.level", ...],
//     "intervals": {"confidence": 0.95, "method": "bootstrap over participants (percentile)", "replicates": 1000,
//                   "bounds": {"lapse_rate": [0.01, 0.08], "cue_weight.pitch": [1.8, null], ...},
//                   "profile_bounds": {...}},
//     "fitted_on": {"study": "study.xml", "actuator": "lra-175hz-drv2605l", "actuator_name": "...",
//                   "actuator_response": {"model": "lra", "resonance_hz": 175, "q": 10, "low_hz": 50,
//                                         "high_hz": 500, "spin_up_s": 0.03, "spin_down_s": 0.045},
//                   "trial_files": [...], "participants": 4, "trials": 480,
//                   "log_likelihood": {"fitted": -300.1, "baseline": -330.4, "default": -410.2, "chance": -665.4}},
//     "leave_one_participant_out": {"participants": [{"participant": "P1", "trials": 120, "fitted": ..., "baseline": ...,
//                                   "default": ..., "chance": ...}, ...], "total": {...}},
//     "warnings": ["cue_weight.pitch: ..."]
//   }
//
// An interval's end is null when unbounded (a weight the trials bound from below only).
// The reader needs `format`, `version` and `constants` (every constant, every cue by name, nothing
// else in it) and reads `fitted_on`'s `study`, `actuator`, `actuator_name` and `actuator_response`
// when there (a file of an older vimg has no `actuator_name` or `actuator_response`: it still
// reads); the other keys are the fit's record and are not read. A file of a later version is
// refused (this reader knows version 1 only). Strict JSON (storage/json_reader.hpp), at most
// kMaxPerceptionModelBytes; every problem is `FILE:LINE: error`.
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "primitives/actuator/response_params.hpp"
#include "primitives/perception/discrimination_choice.hpp"
#include "storage/diagnostic.hpp"
#include "storage/limits.hpp"

namespace vimg {

inline constexpr std::string_view kPerceptionModelFormat = "vimg-perception-model";
inline constexpr int kPerceptionModelVersion = 1;
inline constexpr std::size_t kMaxPerceptionModelBytes = 1 * kMiB;

struct ModelInterval {
  std::string constant;  // "lapse_rate", "cue_weight.level"
  double lower = 0.0, upper = 0.0;                  // stated (bootstrap); upper +infinity: unbounded (null)
  double profile_lower = 0.0, profile_upper = 0.0;  // profile likelihood of the pooled trials
};

struct ModelLikelihoods {
  std::string participant;  // empty for the total
  double trials = 0.0;
  // ln-likelihoods: fitted, the defaults with a fitted lapse rate, the defaults as they are, guessing
  double fitted = 0.0, baseline = 0.0, defaults = 0.0, chance = 0.0;
};

// The actuator the trials were felt through, as the fit rendered the images.
struct ModelActuator {
  std::string given;                       // `fitted_on.actuator`: --actuator as given, or "ideal"
  std::string name;                        // `actuator_name`: the profile's name (empty in older files)
  std::optional<ResponseParams> response;  // `actuator_response` (absent in older files)
  int line = 0;                            // the line of `actuator` in the file read (0: not there)
};

struct PerceptionModel {
  DiscriminationConstants constants;
  // The fit's record (written; of it the reader fills `study` and `actuator` only).
  std::vector<std::string> fitted;
  double interval_confidence = 0.95;
  std::size_t bootstrap_replicates = 0;
  std::vector<ModelInterval> intervals;
  std::string study;
  ModelActuator actuator;
  std::vector<std::string> trial_files;
  std::size_t participants = 0;
  ModelLikelihoods in_sample;
  std::vector<ModelLikelihoods> held_out;
  ModelLikelihoods held_out_total;
  std::vector<std::string> warnings;
};

// The file's text (two-space indented, numbers that read back to the same double).
std::string perception_model_json(const PerceptionModel& model);

struct PerceptionModelLoadResult {
  std::optional<PerceptionModel> model;  // set when there is no error
  std::vector<Diagnostic> diagnostics;
};

// The constants of a JSON object holding `temperature_jnd` (> 0), `lapse_rate` (in [0, 1]) and
// `cue_weight` (every cue by name, each >= 0, no other): MODEL.json's `constants`, and the `model`
// of a `vimg compare` report (storage/study/predicted_confusion.hpp). Other keys of `object` are not
// looked at. The first problem goes to `check`; false then.
class JsonChecker;
class JsonWriter;
struct JsonValue;
bool read_discrimination_constants(JsonChecker& check, const JsonValue& object, DiscriminationConstants& out);
// Writes those three members into the object `w` has open (MODEL.json, the compare and study reports).
void write_discrimination_constants(JsonWriter& w, const DiscriminationConstants& constants);

PerceptionModelLoadResult parse_perception_model(std::string_view json, const std::string& file_name);
PerceptionModelLoadResult load_perception_model(const std::filesystem::path& file);

}  // namespace vimg
