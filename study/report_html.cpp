#include "study/report_svg.hpp"
#include "study/report_tables.hpp"
#include "study/report_writers.hpp"

namespace vimg::study {

namespace {

constexpr const char* kStyle = R"(body{font-family:sans-serif;margin:2em auto;max-width:70em;padding:0 1em;color:#222}
table{border-collapse:collapse;margin:.5em 0 1.5em}caption{text-align:left;font-weight:bold;padding:.3em 0}
th,td{border:1px solid #bbb;padding:.25em .6em;text-align:right}th:first-child,td:first-child{text-align:left}
th{background:#f0f0f0}figure{margin:1em 0;display:inline-block;vertical-align:top}.note{color:#555}
)";

std::string table_html(const ReportTable& t) {
  std::string s = "<table>\n<caption>" + xml_text(t.caption) + "</caption>\n<thead><tr>";
  for (const std::string& h : t.header) s += "<th>" + xml_text(h) + "</th>";
  s += "</tr></thead>\n<tbody>\n";
  for (const auto& row : t.rows) {
    s += "<tr>";
    for (const std::string& cell : row) s += "<td>" + xml_text(cell) + "</td>";
    s += "</tr>\n";
  }
  return s + "</tbody>\n</table>\n";
}

std::string paragraph(const std::string& text, const char* css_class = nullptr) {
  return std::string("<p") + (css_class ? std::string(" class=\"") + css_class + "\"" : "") + ">" + xml_text(text) + "</p>\n";
}

std::string figure(const std::string& svg) { return "<figure>\n" + svg + "</figure>\n"; }

std::string matching_html(const MatchingReport& m) {
  std::string s = "<h2>Matching test</h2>\n";
  s += paragraph("The primitives paper's matching test (section 3): each image of a set is rubbed without being seen and "
                 "matched to one of the set's pictures. Accuracy is correct / trials with its 95 % Wilson score interval.",
                 "note");
  for (const SetReport& set : m.sets) {
    s += "<h3>Set " + xml_text(set.name) + "</h3>\n";
    s += paragraph(set_summary_text(set));
    s += figure(heat_map_svg(comparison_heat_map(set)));
    s += table_html(comparison_table(set));
    s += table_html(per_image_table(set));
    s += table_html(set_participant_table(set));
    if (set.predicted) {
      s += "<h4>Predicted against measured</h4>\n";
      s += figure(heat_map_svg(predicted_heat_map(set)));
      s += figure(heat_map_svg(measured_heat_map(set)));
      s += paragraph(predicted_summary_text(*set.predicted));
      if (const auto t = predicted_table(set)) s += table_html(*t);
    }
  }
  if (!m.set_comparisons.empty()) {
    s += "<h3>Between sets</h3>\n";
    s += table_html(comparisons_table("Welch's t-test on per-participant accuracy; Cohen's d with the pooled SD",
                                      m.set_comparisons, 3));
  }
  return s;
}

std::string location_html(const LocationReport& l) {
  std::string s = "<h2>Location study</h2>\n";
  s += paragraph("The volume paper's location study (section 5): with graphics off, the participant marks where the "
                 "feature meets the bend; the error is the x-z distance from the mark to the intersection.",
                 "note");
  s += figure(location_chart_svg(l));
  s += table_html(metaphor_table(l));
  s += paragraph(location_summary_text(l));
  if (!l.metaphor_comparisons.empty()) {
    s += table_html(comparisons_table("Welch's t-test on the errors (mm); Cohen's d with the pooled SD", l.metaphor_comparisons, 1));
  }
  s += table_html(location_participant_table(l));
  return s;
}

}  // namespace

std::string report_html(const StudyReport& report) {
  std::string s = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>Study report</title>\n<style>";
  s += kStyle;
  s += "</style>\n</head>\n<body>\n<h1>Study report</h1>\n";
  std::string inputs;
  for (const std::string& input : report.inputs) inputs += (inputs.empty() ? "" : ", ") + input;
  s += paragraph("Trial files: " + inputs + ".", "note");
  if (report.matching) s += matching_html(*report.matching);
  if (report.location) s += location_html(*report.location);
  s += paragraph("Written by vimg study report. Distributions from Boost.Math; the formulas are in docs/studies.md.", "note");
  s += "</body>\n</html>\n";
  return s;
}

}  // namespace vimg::study
