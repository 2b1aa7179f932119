#pragma once
// The report's figures as inline SVG (for the self-contained HTML page): heat maps of confusion
// and comparison matrices, and the location study's bar chart of mean errors with their 99 %
// intervals and the chance line (the volume paper's Figure 4). Text is escaped; nothing refers to
// anything outside the SVG, not even the SVG namespace URI (HTML5 gives inline <svg> its namespace).
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "study/report_model.hpp"

namespace vimg::study {

// Text for XML and HTML: & < > " ' escaped, control characters replaced by U+FFFD.
std::string xml_text(std::string_view text);

struct HeatMap {
  std::string title;
  std::vector<std::string> labels;  // rows presented, columns chosen, the same images
  std::vector<std::vector<std::optional<double>>> shade;  // 0 (white) .. 1 (darkest); none: hatched grey
  std::vector<std::vector<std::string>> cells;            // the text in each cell
};

std::string heat_map_svg(const HeatMap& map);

// The comparison matrix of a set: counts, shaded by the share of their row.
HeatMap comparison_heat_map(const SetReport& set);
// Predicted and measured confusion of a set (each row sums to 1).
HeatMap predicted_heat_map(const SetReport& set);
HeatMap measured_heat_map(const SetReport& set);

// Bars: mean error per metaphor; whiskers: the two-sided 99 % t interval; a dashed chance line.
std::string location_chart_svg(const LocationReport& location);

}  // namespace vimg::study
