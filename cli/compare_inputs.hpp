#pragma once
// What `vimg compare`, `vimg separate` and `vimg study fit` read from the command line: the actuator
// profile the images are felt through, and (compare, separate) the identification model's constants
// from MODEL.json. Each prints its errors (FILE:LINE: error) and returns nothing on failure.
#include <optional>
#include <string>

#include "storage/study/perception_model_file.hpp"
#include "study/compare.hpp"

namespace vimg::cli {

// `--actuator P`: a profile file or a shipped profile's name; empty: the ideal actuator.
std::optional<study::CompareActuator> load_compare_actuator(const std::string& argument);

// `--model MODEL.json` (storage/study/perception_model_file.hpp) for images felt through
// `actuator`. The fitted weights hold for what the participants felt, so a model fitted through an
// actuator of another response (model_actuator_mismatch) is refused, an error at the model's
// "actuator" line; a model that does not record the response (of an older vimg, or written by hand)
// and names another actuator, or none, is read with a warning that says so.
std::optional<PerceptionModel> load_model_argument(const std::string& file, const study::CompareActuator& actuator);

// Why `model` may not be used with `actuator` (the recorded response differs), or nothing.
std::optional<std::string> model_actuator_mismatch(const PerceptionModel& model, const study::CompareActuator& actuator);

}  // namespace vimg::cli
