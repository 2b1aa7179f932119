#pragma once
// What `vimg study report` reads (docs/studies.md "The report"): any number of trial files, one per
// participant as the study runners write them, matching and location files mixed (each file's kind
// from its header line), and any number of `vimg compare` reports for --predicted. Everything is
// read and checked before anything is computed or written: a problem is `FILE:LINE: error: ...`.
// Across files, a participant's trial may appear once only (the same file given twice, or two logs
// of one participant that overlap, is an error at the second occurrence), and the sets and their
// images stay within a matching study's limits (kMaxStudySets, kMaxStudyImagesPerSet).
#include <filesystem>
#include <vector>

#include "storage/diagnostic.hpp"
#include "storage/study/trial_table.hpp"
#include "study/report_model.hpp"
#include "study/report_predicted.hpp"

namespace vimg::study {

struct ReportInputs {
  std::vector<std::string> files;  // the trial files as given
  std::vector<MatchingTrial> matching;
  std::vector<LocationTrial> location;
  std::vector<PredictedConfusion> predictions;
  std::vector<Diagnostic> diagnostics;  // errors and warnings of every file, in the order read
  bool ok() const { return !has_errors(diagnostics); }
  bool has_trials() const { return !matching.empty() || !location.empty(); }
};

ReportInputs read_report_inputs(const std::vector<std::filesystem::path>& trial_files,
                                const std::vector<std::filesystem::path>& predicted_files);

// The report of inputs that are ok(): the matching part when there are matching trials, the location
// part when there are location trials, predictions attached to the sets they name. Warnings about
// predictions that serve no set are appended to `warnings`.
StudyReport make_study_report(const ReportInputs& inputs, std::vector<Diagnostic>& warnings);

}  // namespace vimg::study
