#pragma once
// The files `vimg compare --out` writes (docs/studies.md, "Predicting confusion: vimg compare"),
// chosen by the extension, each written atomically (storage/atomic_file.hpp):
//   .json  an object with `images` (the inputs as given), `labels` (their names in warnings),
//          `kinds`, `stsim` (stsim[i][j]: ST-SIM of image i against reference j as vibromaf
//          computes it, unbounded; null where it has no value: CompareResult::stsim),
//          `cue_distances_jnd` (an object: per cue name the matrix of that cue's distances, JNDs),
//          `distance_jnd` (the combined distance), `predicted_confusion` (rows presented, columns
//          chosen), `likely_confused` ([{a, b, p}], indices into images), `warnings`, and what
//          produced them: `sample_rate_hz`, `durations_s`, `canvas_mm`, `actuator`, `exploration`,
//          `model` (the calibration, the JNDs, the choice rule and its constants);
//   .html  a self-contained page: the warnings, heat maps of the predicted confusion and the
//          combined distance as inline SVG with the images' names, the ST-SIM table (with a line on
//          what it means), the actuator, the exploration and the model; no script, style sheet,
//          font or picture from elsewhere;
//   .csv   the long form, one row per ordered pair (i, j) including i = j, i presented:
//          `image_i,image_j,stsim,level_jnd,pitch_jnd,envelope_jnd,distance_jnd,predicted_p`
//          (images as given, RFC 4180 quoting; stsim empty where it has no value; numbers in the
//          shortest form that reads back exactly).
#include <filesystem>
#include <optional>
#include <string>

#include "study/compare.hpp"

namespace vimg::study {

// `model_file`: the MODEL.json whose constants the comparison used (`vimg compare --model`), written as
// `model.model_file` (null when empty: the default constants).
std::string compare_json(const CompareResult& result, const std::string& model_file = {});
std::string compare_html(const CompareResult& result);
std::string compare_csv(const CompareResult& result);

// Whether `vimg compare` writes this extension (.json, .html, .htm, .csv; any case).
bool is_compare_output(const std::filesystem::path& path);

// The report's text for `path`'s extension.
std::string compare_output_text(const std::filesystem::path& path, const CompareResult& result,
                                const std::string& model_file = {});

// Writes the report for `path`'s extension; the error naming the path, or nothing.
std::optional<std::string> write_compare_output(const std::filesystem::path& path, const CompareResult& result);

}  // namespace vimg::study
