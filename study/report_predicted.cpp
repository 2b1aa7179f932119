#include "study/report_predicted.hpp"

#include <cmath>
#include <cstdio>
#include <map>


namespace vimg::study {

namespace {

// Where each of the set's images sits in the prediction; none unless every one is there exactly once.
std::optional<std::vector<std::size_t>> positions(const SetReport& set, const PredictedConfusion& p) {
  std::map<std::string, std::size_t> where;
  std::map<std::string, int> count;
  for (std::size_t k = 0; k < p.stems.size(); ++k) {
    where[p.stems[k]] = k;
    ++count[p.stems[k]];
  }
  std::vector<std::size_t> out;
  for (const std::string& image : set.images) {
    if (count[image] != 1) return std::nullopt;
    out.push_back(where[image]);
  }
  return out;
}

std::optional<PredictedComparison> compare_with(const SetReport& set, const PredictedConfusion& p) {
  const auto at = positions(set, p);
  if (!at) return std::nullopt;
  const std::size_t n = set.images.size();
  PredictedComparison c;
  c.source = p.source;
  c.constants = p.constants;
  c.model_file = p.model_file;
  std::vector<double> predicted_cells, measured_cells;
  for (std::size_t i = 0; i < n; ++i) {
    std::vector<double> row(n);
    double sum = 0.0;
    for (std::size_t j = 0; j < n; ++j) sum += row[j] = p.matrix[(*at)[i]][(*at)[j]];
    if (!(sum > 0.0)) return std::nullopt;  // nothing predicted within the set: it cannot be renormalised
    for (double& x : row) x /= sum;
    std::size_t presented = 0;
    for (const std::size_t count : set.comparison[i]) presented += count;
    std::vector<std::optional<double>> measured(n);
    for (std::size_t j = 0; j < n && presented > 0; ++j) {
      measured[j] = static_cast<double>(set.comparison[i][j]) / static_cast<double>(presented);
      if (i == j) continue;
      predicted_cells.push_back(row[j]);
      measured_cells.push_back(*measured[j]);
    }
    c.predicted.push_back(std::move(row));
    c.measured.push_back(std::move(measured));
  }
  c.off_diagonal_cells = predicted_cells.size();
  c.correlation = pearson_correlation(predicted_cells, measured_cells);
  return c;
}

}  // namespace

std::optional<Diagnostic> low_identification_warning(const SetReport& set) {
  if (!set.predicted) return std::nullopt;
  const auto& m = set.predicted->predicted;
  std::size_t lowest = 0;
  for (std::size_t i = 0; i < m.size(); ++i)
    if (m[i][i] < m[lowest][lowest]) lowest = i;
  if (m.empty() || m[lowest][lowest] >= kIdentifiedTarget) return std::nullopt;
  char share[16];
  std::snprintf(share, sizeof share, "%.0f %%", 100.0 * m[lowest][lowest]);
  return Diagnostic{Diagnostic::Severity::warning, set.predicted->source, 0,
                    "set '" + set.name + "': the prediction identifies '" + set.images[lowest] + "' only " + share +
                        " of the time (below " + std::to_string(static_cast<int>(100.0 * kIdentifiedTarget)) +
                        " %); `vimg separate` on the set's images proposes which tactile parameters to change, and how "
                        "far (docs/separate.md)"};
}

std::vector<Diagnostic> attach_predictions(MatchingReport& report, const std::vector<PredictedConfusion>& predictions) {
  std::vector<bool> used(predictions.size(), false);
  for (SetReport& set : report.sets) {
    for (std::size_t k = 0; k < predictions.size() && !set.predicted; ++k) {
      set.predicted = compare_with(set, predictions[k]);
      if (set.predicted) used[k] = true;
    }
  }
  std::vector<Diagnostic> warnings;
  for (std::size_t k = 0; k < predictions.size(); ++k) {
    if (used[k]) continue;
    warnings.push_back(Diagnostic{Diagnostic::Severity::warning, predictions[k].source, 0,
                                  "its images do not name every image of any set of the trials exactly once (matched by "
                                  "file stem); it is left out of the report"});
  }
  return warnings;
}

}  // namespace vimg::study
