#include "study/report_tables.hpp"

#include <cmath>
#include <cstdio>

namespace vimg::study {

namespace {

std::string count_text(std::size_t n) { return std::to_string(n); }

ReportTable square_table(const SetReport& set, std::string caption, std::string corner) {
  ReportTable t;
  t.caption = std::move(caption);
  t.header.push_back(std::move(corner));
  for (const std::string& image : set.images) t.header.push_back(image);
  return t;
}

}  // namespace

std::string fixed_text(double value, int decimals) {
  if (!std::isfinite(value)) return "n/a";
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
  std::string text = buffer;
  if (text.find_first_not_of("-0.") == std::string::npos && text[0] == '-') text.erase(0, 1);  // no "-0.0"
  return text;
}

std::string percent_text(double fraction) { return fixed_text(100.0 * fraction, 1) + " %"; }

std::string optional_fixed_text(const std::optional<double>& value, int decimals) {
  return value ? fixed_text(*value, decimals) : "n/a";
}

std::string p_value_text(double p) {
  if (!std::isfinite(p)) return "n/a";
  if (p < 0.0001) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.2e", p);
    return buffer;
  }
  return fixed_text(p, 4);
}

std::string interval_text(const std::optional<Interval>& interval, int decimals, double scale) {
  if (!interval) return "n/a";
  return fixed_text(interval->lower * scale, decimals) + "\u2013" + fixed_text(interval->upper * scale, decimals);
}

std::string set_summary_text(const SetReport& set) {
  std::string ci = set.accuracy_ci95 ? " (95 % Wilson interval " + interval_text(set.accuracy_ci95, 1, 100.0) + " %)" : "";
  return count_text(set.trials) + " trials by " + count_text(set.participants.size()) + " participant" +
         (set.participants.size() == 1 ? "" : "s") + "; accuracy " + percent_text(set.accuracy) + ci + " against chance " +
         percent_text(set.chance) + " (" + count_text(set.images.size()) + " images).";
}

ReportTable comparison_table(const SetReport& set) {
  ReportTable t = square_table(set, "Comparison matrix: counts, rows presented, columns chosen", "presented \u2193 chosen \u2192");
  t.header.push_back("total");
  std::vector<std::size_t> column_totals(set.images.size(), 0);
  for (std::size_t i = 0; i < set.images.size(); ++i) {
    std::vector<std::string> row{set.images[i]};
    std::size_t total = 0;
    for (std::size_t j = 0; j < set.images.size(); ++j) {
      row.push_back(count_text(set.comparison[i][j]));
      total += set.comparison[i][j];
      column_totals[j] += set.comparison[i][j];
    }
    row.push_back(count_text(total));
    t.rows.push_back(std::move(row));
  }
  std::vector<std::string> totals{"total"};
  for (const std::size_t c : column_totals) totals.push_back(count_text(c));
  totals.push_back(count_text(set.trials));
  t.rows.push_back(std::move(totals));
  return t;
}

ReportTable per_image_table(const SetReport& set) {
  ReportTable t{"Per image: each image against the rest of its set",
                {"image", "TP", "FN", "FP", "TN", "hit rate", "false-alarm rate"},
                {}};
  for (const ImageCounts& c : set.per_image) {
    t.rows.push_back({c.image, count_text(c.tp), count_text(c.fn), count_text(c.fp), count_text(c.tn),
                      optional_fixed_text(c.hit_rate, 3), optional_fixed_text(c.false_alarm_rate, 3)});
  }
  return t;
}

ReportTable set_participant_table(const SetReport& set) {
  ReportTable t{"Accuracy per participant", {"participant", "trials", "correct", "accuracy"}, {}};
  for (const ParticipantAccuracy& p : set.participants) {
    t.rows.push_back({p.participant, count_text(p.trials), count_text(p.correct), percent_text(p.accuracy)});
  }
  return t;
}

std::optional<ReportTable> predicted_table(const SetReport& set) {
  if (!set.predicted) return std::nullopt;
  ReportTable t = square_table(set, "Predicted / measured confusion: rows presented, columns chosen, each row sums to 1",
                               "presented \u2193 chosen \u2192");
  for (std::size_t i = 0; i < set.images.size(); ++i) {
    std::vector<std::string> row{set.images[i]};
    for (std::size_t j = 0; j < set.images.size(); ++j) {
      row.push_back(fixed_text(set.predicted->predicted[i][j], 2) + " / " + optional_fixed_text(set.predicted->measured[i][j], 2));
    }
    t.rows.push_back(std::move(row));
  }
  return t;
}

std::string predicted_summary_text(const PredictedComparison& p) {
  std::string r = p.correlation ? "r = " + fixed_text(*p.correlation, 3)
                                : "r is not defined (one side is the same in every cell, e.g. no confusion was measured)";
  std::string model;
  if (!p.model_file.empty()) model = ", made with the model " + p.model_file;
  if (p.constants) {
    char text[160];
    std::snprintf(text, sizeof text, "temperature %.3g JND, lapse rate %.3g, cue weights", p.constants->temperature_jnd,
                  p.constants->lapse_rate);
    std::string weights = text;
    for (std::size_t c = 0; c < kCueCount; ++c) {
      std::snprintf(text, sizeof text, "%s %s %.3g", c ? "," : "", std::string(cue_name(c)).c_str(), p.constants->cue_weight[c]);
      weights += text;
    }
    model += " (" + weights + ")";
  }
  return "Prediction from " + p.source + model + ". Pearson correlation of predicted and measured confusion over the " +
         count_text(p.off_diagonal_cells) + " off-diagonal cells: " + r + ".";
}

ReportTable comparisons_table(const std::string& caption, const std::vector<GroupComparison>& comparisons, int mean_decimals) {
  ReportTable t{caption, {"A", "B", "n A", "n B", "mean A", "mean B", "SD A", "SD B", "t", "df", "p (two-sided)", "Cohen's d"}, {}};
  for (const GroupComparison& c : comparisons) {
    t.rows.push_back({c.a, c.b, count_text(c.summary_a.n), count_text(c.summary_b.n), fixed_text(c.summary_a.mean, mean_decimals),
                      fixed_text(c.summary_b.mean, mean_decimals), optional_fixed_text(c.summary_a.sd, mean_decimals + 1),
                      optional_fixed_text(c.summary_b.sd, mean_decimals + 1),
                      c.welch ? fixed_text(c.welch->t, 3) : "n/a", c.welch ? fixed_text(c.welch->df, 2) : "n/a",
                      c.welch ? p_value_text(c.welch->p) : "n/a", optional_fixed_text(c.cohens_d, 3)});
  }
  return t;
}

ReportTable metaphor_table(const LocationReport& location) {
  ReportTable t{"Location error per metaphor (x-z distance from mark to target)",
                {"metaphor", "n", "mean (mm)", "SD (mm)", "99 % CI of the mean (mm)", "chance (mm)"},
                {}};
  for (const MetaphorReport& m : location.metaphors) {
    t.rows.push_back({m.name, count_text(m.n), fixed_text(m.mean_mm, 1), optional_fixed_text(m.sd_mm, 1),
                      interval_text(m.ci99_mm, 1), fixed_text(m.chance_mm, 1)});
  }
  return t;
}

ReportTable location_participant_table(const LocationReport& location) {
  ReportTable t{"Mean error per participant (mm; trials in brackets)", {"participant"}, {}};
  for (const MetaphorReport& m : location.metaphors) t.header.push_back(m.name);
  for (const ParticipantLocation& p : location.participants) {
    std::vector<std::string> row{p.participant};
    for (const ParticipantMetaphorMean& m : p.metaphors) {
      row.push_back(m.n > 0 ? fixed_text(m.mean_mm, 1) + " (" + count_text(m.n) + ")" : "\u2013");
    }
    t.rows.push_back(std::move(row));
  }
  return t;
}

std::string location_summary_text(const LocationReport& location) {
  const Workspace& w = location.workspace;
  return "Chance: " + fixed_text(location.chance_mm, 1) +
         " mm, the expected x-z distance from a mark placed uniformly in the workspace (x " + fixed_text(w.x_min_mm, 0) +
         " to " + fixed_text(w.x_max_mm, 0) + " mm, z " + fixed_text(w.z_min_mm, 0) + " to " + fixed_text(w.z_max_mm, 0) +
         " mm) to each trial's target, averaged over the trials (docs/studies.md).";
}

}  // namespace vimg::study
