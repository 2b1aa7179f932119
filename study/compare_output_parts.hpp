#pragma once
// The parts of `vimg compare`'s reports (compare_output.hpp) that `vimg separate`'s reports
// (separate_output.hpp) repeat word for word: how the images were felt (actuator, exploration,
// model) and a matrix, as JSON and as HTML.
#include <string>
#include <vector>

#include "storage/export/json_writer.hpp"
#include "study/compare.hpp"
#include "study/report_svg.hpp"

namespace vimg::study {

// A matrix as nested arrays; null where a value is not finite.
void matrix(JsonWriter& w, const PerceptionMatrix& m);
// The objects `actuator`, `exploration` and `model` of compare_json.
void describe_actuator(JsonWriter& w, const CompareActuator& a);
void describe_exploration(JsonWriter& w, const CompareResult& r);
void describe_model(JsonWriter& w, const CompareResult& r, const std::string& model_file);

// A number with `decimals` decimals; an en dash when not finite.
std::string number_text(double v, int decimals);
// A heat map of m (rows presented, columns chosen) with the cells' values to 2 decimals.
HeatMap matrix_heat_map(std::vector<std::string> labels, const PerceptionMatrix& m, std::string title);
// "How the images were felt": the actuator, canvas, exploration and model, as an HTML section.
std::string setup_html(const CompareResult& r);

}  // namespace vimg::study
