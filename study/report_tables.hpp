#pragma once
// The report's tables and sentences as text, built once from a StudyReport and laid out by both the
// HTML and the Markdown writer (study/report_writers.hpp), so the two always say the same thing.
#include <optional>
#include <string>
#include <vector>

#include "study/report_model.hpp"

namespace vimg::study {

struct ReportTable {
  std::string caption;
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
};

// Numbers as the report prints them (C locale): "98.5 %", "14.1", "0.0123", "n/a" for none.
std::string percent_text(double fraction);
std::string fixed_text(double value, int decimals);
std::string optional_fixed_text(const std::optional<double>& value, int decimals);
std::string p_value_text(double p);
std::string interval_text(const std::optional<Interval>& interval, int decimals, double scale = 1.0);

// One set: a sentence with trials, accuracy, its Wilson interval and chance; the comparison matrix
// (counts with totals, Tables 1-2), per image counts (Tables 3-5), per participant accuracy, and,
// with a prediction, predicted against measured confusion.
std::string set_summary_text(const SetReport& set);
ReportTable comparison_table(const SetReport& set);
ReportTable per_image_table(const SetReport& set);
ReportTable set_participant_table(const SetReport& set);
std::optional<ReportTable> predicted_table(const SetReport& set);
std::string predicted_summary_text(const PredictedComparison& predicted);

// Welch's t-test and Cohen's d per pair of groups.
// `mean_decimals`: how the groups' means print (3 for accuracies, 1 for millimetres).
ReportTable comparisons_table(const std::string& caption, const std::vector<GroupComparison>& comparisons, int mean_decimals);

// Location: one row per metaphor (n, mean, SD, 99 % CI, chance), each participant's means.
ReportTable metaphor_table(const LocationReport& location);
ReportTable location_participant_table(const LocationReport& location);
std::string location_summary_text(const LocationReport& location);

}  // namespace vimg::study
