// Fuzzes the strict JSON reader of `vimg study report --predicted` and the predicted confusion read
// from it: any bytes give one located error or a value within the reader's bounds, never a crash.
// A prediction that reads is attached to a set of its own images and the report is written in all
// three forms; the JSON report reads back with the same reader and names the same images.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

#include "check_messages.hpp"
#include "storage/json_reader.hpp"
#include "study/report_predicted.hpp"
#include "study/report_writers.hpp"

namespace {

using vimg::JsonValue;

void check_value(const JsonValue& v, std::size_t depth, std::size_t& count) {
  if (++count > vimg::kMaxJsonValues || depth > vimg::kMaxJsonDepth + 1) std::abort();
  if (v.line < 1) std::abort();
  if (v.kind == JsonValue::Kind::number && !std::isfinite(v.number)) std::abort();
  if (v.kind == JsonValue::Kind::object && v.keys.size() != v.items.size()) std::abort();
  if (v.kind != JsonValue::Kind::object && !v.keys.empty()) std::abort();
  for (std::size_t i = 0; i < v.keys.size(); ++i) {
    for (std::size_t k = 0; k < i; ++k) {
      if (v.keys[k] == v.keys[i]) std::abort();  // duplicate keys are refused
    }
  }
  for (const JsonValue& item : v.items) check_value(item, depth + 1, count);
}

// A report of one set whose images are the prediction's first stems, everyone always right.
vimg::study::StudyReport report_for(const vimg::PredictedConfusion& p) {
  vimg::study::StudyReport report;
  report.inputs = {"fuzz.csv"};
  vimg::study::MatchingReport m;
  vimg::study::SetReport set;
  set.name = "fuzz";
  for (const std::string& stem : p.stems) {
    if (set.images.size() == 8) break;
    bool seen = false;
    for (const std::string& image : set.images) seen = seen || image == stem;
    if (!seen) set.images.push_back(stem);
  }
  std::sort(set.images.begin(), set.images.end());
  const std::size_t n = set.images.size();
  set.comparison.assign(n, std::vector<std::size_t>(n, 0));
  for (std::size_t i = 0; i < n; ++i) set.comparison[i][i] = 1;
  set.trials = set.correct = n;
  set.accuracy = 1.0;
  m.sets.push_back(set);
  report.matching = m;
  return report;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const vimg::JsonParseResult json = vimg::parse_json(text, "fuzz.json");
  if (json.value.has_value() == vimg::has_errors(json.diagnostics)) std::abort();  // a value iff no error
  if (json.diagnostics.size() > 1) std::abort();  // the first problem stops the reader
  vimg::fuzz::check_messages(json.diagnostics);
  if (json.value) {
    std::size_t count = 0;
    check_value(*json.value, 1, count);
  }

  const vimg::PredictedLoadResult predicted = vimg::parse_predicted_confusion(text, "fuzz.json");
  if (predicted.predicted.has_value() == vimg::has_errors(predicted.diagnostics)) std::abort();
  vimg::fuzz::check_messages(predicted.diagnostics);
  if (!predicted.predicted) return 0;
  const vimg::PredictedConfusion& p = *predicted.predicted;
  const std::size_t n = p.stems.size();
  if (n == 0 || n > vimg::kMaxPredictedImages || p.matrix.size() != n) std::abort();
  for (const auto& row : p.matrix) {
    double sum = 0.0;
    if (row.size() != n) std::abort();
    for (const double x : row) {
      if (!(x >= 0.0 && x <= 1.0)) std::abort();
      sum += x;
    }
    if (!(std::abs(sum - 1.0) <= vimg::kPredictedRowSumTolerance)) std::abort();
  }
  for (const std::string& stem : p.stems) {
    if (stem.empty()) std::abort();
  }

  vimg::study::StudyReport report = report_for(p);
  (void)vimg::study::attach_predictions(*report.matching, {p});
  const vimg::study::SetReport& set = report.matching->sets.front();
  if (set.predicted) {
    for (const auto& row : set.predicted->predicted) {
      double sum = 0.0;
      for (const double x : row) sum += x;
      if (!(std::abs(sum - 1.0) <= 1e-9)) std::abort();  // renormalised within the set
    }
    if (set.predicted->correlation && !(std::abs(*set.predicted->correlation) <= 1.0)) std::abort();
  }
  const std::string out = vimg::study::report_json(report);
  const vimg::JsonParseResult back = vimg::parse_json(out, "report.json");
  if (!back.value) std::abort();  // the writer's JSON is JSON
  const JsonValue* sets = back.value->find("sets");
  if (!sets || sets->items.size() != 1) std::abort();
  const JsonValue* images = sets->items[0].find("images");
  if (!images || images->items.size() != set.images.size()) std::abort();
  for (std::size_t i = 0; i < set.images.size(); ++i) {
    if (images->items[i].text != set.images[i]) std::abort();  // names survive the round trip
  }
  (void)vimg::study::report_html(report);
  (void)vimg::study::report_markdown(report);
  return 0;
}
