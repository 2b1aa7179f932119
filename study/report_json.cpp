#include <cmath>
#include <optional>

#include "storage/export/json_writer.hpp"
#include "storage/study/perception_model_file.hpp"
#include "study/report_writers.hpp"

namespace vimg::study {

namespace {

// Every number of the report: null when it is not finite (a file may hold numbers so large that a
// mean overflows; JsonWriter would write such a value as 0).
void optional_number(JsonWriter& w, const std::optional<double>& value) {
  if (value && std::isfinite(*value)) {
    w.number(*value);
  } else {
    w.null();
  }
}

void interval(JsonWriter& w, const std::optional<Interval>& value) {
  if (!value) return w.null();
  w.begin_array();
  optional_number(w, value->lower);
  optional_number(w, value->upper);
  w.end_array();
}

void comparison(JsonWriter& w, const GroupComparison& c) {
  w.begin_object();
  w.key("a");
  w.string(c.a);
  w.key("b");
  w.string(c.b);
  w.key("n_a");
  w.integer(static_cast<long long>(c.summary_a.n));
  w.key("n_b");
  w.integer(static_cast<long long>(c.summary_b.n));
  w.key("mean_a");
  optional_number(w, c.summary_a.mean);
  w.key("mean_b");
  optional_number(w, c.summary_b.mean);
  w.key("sd_a");
  optional_number(w, c.summary_a.sd);
  w.key("sd_b");
  optional_number(w, c.summary_b.sd);
  w.key("t");
  optional_number(w, c.welch ? std::optional(c.welch->t) : std::nullopt);
  w.key("df");
  optional_number(w, c.welch ? std::optional(c.welch->df) : std::nullopt);
  w.key("p");
  optional_number(w, c.welch ? std::optional(c.welch->p) : std::nullopt);
  w.key("cohens_d");
  optional_number(w, c.cohens_d);
  w.end_object();
}

void comparisons(JsonWriter& w, const char* all_key, const std::vector<GroupComparison>& all) {
  w.key("ttest");
  if (all.size() == 1) {
    comparison(w, all.front());
  } else {
    w.null();
  }
  w.key(all_key);
  w.begin_array();
  for (const GroupComparison& c : all) comparison(w, c);
  w.end_array();
}

template <class Matrix, class Cell>
void matrix(JsonWriter& w, const Matrix& m, Cell cell) {
  w.begin_array();
  for (const auto& row : m) {
    w.begin_array();
    for (const auto& value : row) cell(value);
    w.end_array();
  }
  w.end_array();
}

void predicted(JsonWriter& w, const PredictedComparison& p) {
  w.begin_object();
  w.key("source");
  w.string(p.source);
  w.key("model_file");
  if (p.model_file.empty()) {
    w.null();
  } else {
    w.string(p.model_file);
  }
  if (p.constants) {
    w.key("constants");
    w.begin_object();
    write_discrimination_constants(w, *p.constants);
    w.end_object();
  }
  w.key("predicted");
  matrix(w, p.predicted, [&](double x) { optional_number(w, x); });
  w.key("measured");
  matrix(w, p.measured, [&](const std::optional<double>& x) { optional_number(w, x); });
  w.key("off_diagonal_cells");
  w.integer(static_cast<long long>(p.off_diagonal_cells));
  w.key("correlation");
  optional_number(w, p.correlation);
  w.end_object();
}

void set_report(JsonWriter& w, const SetReport& s) {
  w.begin_object();
  w.key("name");
  w.string(s.name);
  w.key("images");
  w.begin_array();
  for (const std::string& image : s.images) w.string(image);
  w.end_array();
  w.key("comparison");
  matrix(w, s.comparison, [&](std::size_t x) { w.integer(static_cast<long long>(x)); });
  w.key("trials");
  w.integer(static_cast<long long>(s.trials));
  w.key("correct");
  w.integer(static_cast<long long>(s.correct));
  w.key("accuracy");
  optional_number(w, s.accuracy);
  w.key("accuracy_ci95");
  interval(w, s.accuracy_ci95);
  w.key("chance");
  optional_number(w, s.chance);
  w.key("per_image");
  w.begin_array();
  for (const ImageCounts& c : s.per_image) {
    w.begin_object();
    w.key("image");
    w.string(c.image);
    for (const auto& [name, value] : {std::pair{"tp", c.tp}, {"fn", c.fn}, {"fp", c.fp}, {"tn", c.tn}}) {
      w.key(name);
      w.integer(static_cast<long long>(value));
    }
    w.key("hit_rate");
    optional_number(w, c.hit_rate);
    w.key("false_alarm_rate");
    optional_number(w, c.false_alarm_rate);
    w.end_object();
  }
  w.end_array();
  w.key("participants");
  w.begin_array();
  for (const ParticipantAccuracy& p : s.participants) {
    w.begin_object();
    w.key("participant");
    w.string(p.participant);
    w.key("trials");
    w.integer(static_cast<long long>(p.trials));
    w.key("correct");
    w.integer(static_cast<long long>(p.correct));
    w.key("accuracy");
    optional_number(w, p.accuracy);
    w.end_object();
  }
  w.end_array();
  if (s.predicted) {
    w.key("predicted");
    predicted(w, *s.predicted);
  }
  w.end_object();
}

void matching_part(JsonWriter& w, const MatchingReport& m) {
  w.key("sets");
  w.begin_array();
  for (const SetReport& s : m.sets) set_report(w, s);
  w.end_array();
  comparisons(w, "set_comparisons", m.set_comparisons);
}

void location_part(JsonWriter& w, const LocationReport& l) {
  const Workspace& ws = l.workspace;
  w.key("workspace_mm");
  w.begin_object();
  w.key("x");
  interval(w, Interval{ws.x_min_mm, ws.x_max_mm});
  w.key("z");
  interval(w, Interval{ws.z_min_mm, ws.z_max_mm});
  w.end_object();
  w.key("chance_mm");
  optional_number(w, l.chance_mm);
  w.key("metaphors");
  w.begin_array();
  for (const MetaphorReport& r : l.metaphors) {
    w.begin_object();
    w.key("name");
    w.string(r.name);
    w.key("n");
    w.integer(static_cast<long long>(r.n));
    w.key("mean_mm");
    optional_number(w, r.mean_mm);
    w.key("sd_mm");
    optional_number(w, r.sd_mm);
    w.key("ci99_mm");
    interval(w, r.ci99_mm);
    w.key("chance_mm");
    optional_number(w, r.chance_mm);
    w.end_object();
  }
  w.end_array();
  comparisons(w, "metaphor_comparisons", l.metaphor_comparisons);
  w.key("participants");
  w.begin_array();
  for (const ParticipantLocation& p : l.participants) {
    w.begin_object();
    w.key("participant");
    w.string(p.participant);
    w.key("metaphors");
    w.begin_array();
    for (const ParticipantMetaphorMean& m : p.metaphors) {
      w.begin_object();
      w.key("name");
      w.string(m.metaphor);
      w.key("n");
      w.integer(static_cast<long long>(m.n));
      w.key("mean_mm");
      if (m.n > 0) {
        optional_number(w, m.mean_mm);
      } else {
        w.null();
      }
      w.end_object();
    }
    w.end_array();
    w.end_object();
  }
  w.end_array();
}

}  // namespace

std::string report_json(const StudyReport& report) {
  JsonWriter w;
  w.begin_object();
  w.key("report");
  w.string("vimg study report");
  w.key("study");
  const bool both = report.matching && report.location;
  w.string(both ? "both" : report.matching ? "matching" : "location");
  w.key("inputs");
  w.begin_array();
  for (const std::string& input : report.inputs) w.string(input);
  w.end_array();
  if (report.matching) {
    if (both) {
      w.key("matching");
      w.begin_object();
    }
    matching_part(w, *report.matching);
    if (both) w.end_object();
  }
  if (report.location) {
    if (both) {
      w.key("location");
      w.begin_object();
    }
    location_part(w, *report.location);
    if (both) w.end_object();
  }
  w.end_object();
  return w.take();
}

}  // namespace vimg::study
