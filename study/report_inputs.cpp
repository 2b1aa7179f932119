#include "study/report_inputs.hpp"

#include <map>
#include <set>
#include <string>
#include <tuple>
#include <utility>

#include "storage/limits.hpp"
#include "study/report_location.hpp"
#include "study/report_matching.hpp"

namespace vimg::study {

namespace {

// A file whose first line is neither header: the reader's own words when it could not be read or
// holds no line yet (an empty file is a warning), otherwise one error naming both headers.
void unknown_kind(const std::filesystem::path& file, std::vector<Diagnostic>& out) {
  TrialTableResult<MatchingTrial> as_matching = read_matching_trials(file);
  if (as_matching.ok()) return append_diagnostics(out, std::move(as_matching.diagnostics));
  TrialTableResult<LocationTrial> as_location = read_location_trials(file);
  if (as_location.ok()) return append_diagnostics(out, std::move(as_location.diagnostics));
  for (const Diagnostic& d : as_matching.diagnostics) {
    if (d.severity == Diagnostic::Severity::error && d.line == 0) return append_diagnostics(out, std::move(as_matching.diagnostics));
  }
  out.push_back(Diagnostic{Diagnostic::Severity::error, file.string(), 1,
                           "not a trial file: the first line is neither the matching test's header (participant,set,trial,...) "
                           "nor the location study's (participant,trial,metaphor,...)"});
}

// Where each participant's trials were first seen: refuses a trial given twice across files.
class TrialRegistry {
 public:
  // Row `index` of `file` (its line is index + 2: the header, then one line per row).
  bool add(const std::string& file, std::size_t index, const std::string& kind, const std::string& participant, int trial,
           std::vector<Diagnostic>& out) {
    const int line = static_cast<int>(index) + 2;
    const auto [it, inserted] = seen_.try_emplace({kind, participant, trial}, file, line);
    if (inserted) return true;
    out.push_back(Diagnostic{Diagnostic::Severity::error, file, line,
                             "participant '" + participant + "' trial " + std::to_string(trial) + " is also at " + it->second.first +
                                 ":" + std::to_string(it->second.second) + " (a file given twice, or two logs that overlap)"});
    return false;
  }

 private:
  std::map<std::tuple<std::string, std::string, int>, std::pair<std::string, int>> seen_;
};

// The matching study's limits on sets and images, counted across every file.
class SetLimits {
 public:
  bool add(const std::string& file, std::size_t index, const MatchingTrial& t, std::vector<Diagnostic>& out) {
    const int line = static_cast<int>(index) + 2;
    if (!images_.count(t.set) && images_.size() >= kMaxStudySets) {
      out.push_back(Diagnostic{Diagnostic::Severity::error, file, line,
                               "more than " + std::to_string(kMaxStudySets) + " image sets across the trial files (a study's limit)"});
      return false;
    }
    std::set<std::string>& images = images_[t.set];
    images.insert(t.presented);
    images.insert(t.chosen);
    if (images.size() > kMaxStudyImagesPerSet) {
      out.push_back(Diagnostic{Diagnostic::Severity::error, file, line,
                               "set '" + t.set + "' names more than " + std::to_string(kMaxStudyImagesPerSet) +
                                   " images across the trial files (a study's limit)"});
      return false;
    }
    return true;
  }

 private:
  std::map<std::string, std::set<std::string>> images_;
};

}  // namespace

ReportInputs read_report_inputs(const std::vector<std::filesystem::path>& trial_files,
                                const std::vector<std::filesystem::path>& predicted_files) {
  ReportInputs in;
  TrialRegistry registry;
  SetLimits limits;
  for (const std::filesystem::path& file : trial_files) {
    const std::string name = file.string();
    in.files.push_back(name);
    const TrialFileKind kind = trial_file_kind(file);
    if (kind == TrialFileKind::matching) {
      TrialTableResult<MatchingTrial> r = read_matching_trials(file);
      const bool ok = r.ok();
      append_diagnostics(in.diagnostics, std::move(r.diagnostics));
      for (std::size_t k = 0; ok && k < r.rows.size(); ++k) {
        const MatchingTrial& t = r.rows[k];
        if (!registry.add(name, k, "matching", t.participant, t.trial, in.diagnostics)) break;
        if (!limits.add(name, k, t, in.diagnostics)) break;
        in.matching.push_back(t);
      }
    } else if (kind == TrialFileKind::location) {
      TrialTableResult<LocationTrial> r = read_location_trials(file);
      const bool ok = r.ok();
      append_diagnostics(in.diagnostics, std::move(r.diagnostics));
      for (std::size_t k = 0; ok && k < r.rows.size(); ++k) {
        const LocationTrial& t = r.rows[k];
        if (!registry.add(name, k, "location", t.participant, t.trial, in.diagnostics)) break;
        in.location.push_back(t);
      }
    } else {
      unknown_kind(file, in.diagnostics);
    }
  }
  for (const std::filesystem::path& file : predicted_files) {
    PredictedLoadResult r = load_predicted_confusion(file);
    append_diagnostics(in.diagnostics, std::move(r.diagnostics));
    if (r.predicted) in.predictions.push_back(std::move(*r.predicted));
  }
  return in;
}

StudyReport make_study_report(const ReportInputs& inputs, std::vector<Diagnostic>& warnings) {
  StudyReport report;
  report.inputs = inputs.files;
  if (!inputs.matching.empty()) {
    report.matching = make_matching_report(inputs.matching);
    append_diagnostics(warnings, attach_predictions(*report.matching, inputs.predictions));
    for (const SetReport& set : report.matching->sets) {
      if (auto low = low_identification_warning(set)) warnings.push_back(std::move(*low));
    }
  } else {
    for (const PredictedConfusion& p : inputs.predictions) {
      warnings.push_back(Diagnostic{Diagnostic::Severity::warning, p.source, 0, "no matching trials to compare it with; left out"});
    }
  }
  if (!inputs.location.empty()) report.location = make_location_report(inputs.location);
  return report;
}

}  // namespace vimg::study
