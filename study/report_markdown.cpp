#include "study/report_tables.hpp"
#include "study/report_writers.hpp"

namespace vimg::study {

namespace {

// A cell of a Markdown table: '|' and '\' escaped, line breaks (never expected) as spaces.
std::string cell_text(const std::string& text) {
  std::string out;
  for (const char c : text) {
    if (c == '|' || c == '\\') out += '\\';
    out += (c == '\n' || c == '\r') ? ' ' : c;
  }
  return out;
}

std::string table_markdown(const ReportTable& t) {
  std::string s = "**" + cell_text(t.caption) + "**\n\n|";
  for (const std::string& h : t.header) s += " " + cell_text(h) + " |";
  s += "\n|";
  for (std::size_t k = 0; k < t.header.size(); ++k) s += k == 0 ? " --- |" : " ---: |";
  s += "\n";
  for (const auto& row : t.rows) {
    s += "|";
    for (const std::string& cell : row) s += " " + cell_text(cell) + " |";
    s += "\n";
  }
  return s + "\n";
}

std::string matching_markdown(const MatchingReport& m) {
  std::string s = "## Matching test\n\n";
  for (const SetReport& set : m.sets) {
    s += "### Set " + cell_text(set.name) + "\n\n" + set_summary_text(set) + "\n\n";
    s += table_markdown(comparison_table(set));
    s += table_markdown(per_image_table(set));
    s += table_markdown(set_participant_table(set));
    if (set.predicted) {
      s += predicted_summary_text(*set.predicted) + "\n\n";
      if (const auto t = predicted_table(set)) s += table_markdown(*t);
    }
  }
  if (!m.set_comparisons.empty()) {
    s += "### Between sets\n\n";
    s += table_markdown(comparisons_table("Welch's t-test on per-participant accuracy; Cohen's d with the pooled SD",
                                          m.set_comparisons, 3));
  }
  return s;
}

std::string location_markdown(const LocationReport& l) {
  std::string s = "## Location study\n\n";
  s += table_markdown(metaphor_table(l));
  s += location_summary_text(l) + "\n\n";
  if (!l.metaphor_comparisons.empty()) {
    s += table_markdown(comparisons_table("Welch's t-test on the errors (mm); Cohen's d with the pooled SD", l.metaphor_comparisons, 1));
  }
  s += table_markdown(location_participant_table(l));
  return s;
}

}  // namespace

std::string report_markdown(const StudyReport& report) {
  std::string s = "# Study report\n\nTrial files:";
  for (const std::string& input : report.inputs) s += " `" + input + "`";
  s += "\n\n";
  if (report.matching) s += matching_markdown(*report.matching);
  if (report.location) s += location_markdown(*report.location);
  s += "Written by `vimg study report`; distributions from Boost.Math; formulas in docs/studies.md.\n";
  return s;
}

}  // namespace vimg::study
