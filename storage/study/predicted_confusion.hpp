#pragma once
// The predicted confusion that `vimg compare` writes (its JSON report; docs/studies.md "Predicted
// against measured"), read for `vimg study report --predicted` (study/report_predicted.hpp sets it
// beside the measured one). Two keys are needed: `images` (the image paths as compare was given
// them) and `predicted_confusion` (rows presented, columns chosen, each row summing to 1). When
// `model` holds the discrimination constants the prediction was made with (`temperature_jnd`,
// `lapse_rate`, `cue_weight` by cue name: the defaults, or those of `vimg compare --model`) and
// `model_file` (the MODEL.json given, or null), they are read too, and must be well formed; other
// keys are ignored. The reader is strict (storage/json_reader.hpp); every problem is
// `FILE:LINE: error`.
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "primitives/perception/discrimination_choice.hpp"
#include "storage/diagnostic.hpp"
#include "storage/limits.hpp"

namespace vimg {

inline constexpr std::size_t kMaxPredictedJsonBytes = 8 * kMiB;
inline constexpr std::size_t kMaxPredictedImages = 1024;
// A row of predicted_confusion may miss 1 by this much (the numbers are rounded when written).
inline constexpr double kPredictedRowSumTolerance = 1e-6;

struct PredictedConfusion {
  std::string source;              // the file as given
  std::vector<std::string> stems;  // image names as trial files name them (study_image_name)
  std::vector<std::vector<double>> matrix;  // [presented][chosen], in the order of `stems`
  std::optional<DiscriminationConstants> constants;  // when the report names them
  std::string model_file;  // the MODEL.json of `vimg compare --model`; empty: none (the defaults)
};

struct PredictedLoadResult {
  std::optional<PredictedConfusion> predicted;  // set when there is no error
  std::vector<Diagnostic> diagnostics;
};

PredictedLoadResult parse_predicted_confusion(std::string_view json, const std::string& file_name);
// Reads at most kMaxPredictedJsonBytes through read_regular_file.
PredictedLoadResult load_predicted_confusion(const std::filesystem::path& file);

}  // namespace vimg
