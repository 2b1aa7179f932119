#pragma once
// What `vimg compare` and `vimg study fit` both read from the command line: the actuator profile
// the images are felt through, and (compare) the discrimination model's constants from MODEL.json.
// Each prints its errors (FILE:LINE: error) and returns nothing on failure.
#include <optional>
#include <string>

#include "storage/study/perception_model_file.hpp"
#include "study/compare.hpp"

namespace vimg::cli {

// `--actuator P`: a profile file or a shipped profile's name; empty: the ideal actuator.
std::optional<study::CompareActuator> load_compare_actuator(const std::string& argument);

// `--model MODEL.json` (storage/study/perception_model_file.hpp).
std::optional<PerceptionModel> load_model_argument(const std::string& file);

}  // namespace vimg::cli
