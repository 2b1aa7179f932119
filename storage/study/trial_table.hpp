#pragma once
// Trial files (CSV, docs/format-studies.md "Trial files"): one schema per study kind, a row per trial, written
// one synced line at a time by storage/study/trial_log.hpp and read whole by the report.
//
//   matching: participant,set,trial,presented,chosen,correct,rub_s,response_s,path_mm,time_utc
//   location: participant,trial,metaphor,seed,target_x_mm,target_z_mm,mark_x_mm,mark_y_mm,mark_z_mm,error_mm,explore_s,time_utc
//
// Cells hold no comma, quote or line break (names are checked where they are made: participant IDs,
// set names and image stems), so a row is its cells joined by commas; numbers are written in the
// shortest text that reads back to the same double (storage/number_text.hpp).
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "storage/diagnostic.hpp"
#include "storage/study/study_file.hpp"

namespace vimg {

struct MatchingTrial {
  std::string participant;
  std::string set;
  int trial = 0;  // counts from 1 across the whole study
  std::string presented;  // images by file stem (study_image_name)
  std::string chosen;
  bool correct = false;  // presented == chosen; 0/1 in the file
  double rub_s = 0;       // from the trial's start to "Answer"
  double response_s = 0;  // from "Answer" to the choice
  double path_mm = 0;     // length of the rubbing path
  std::string time_utc;   // ISO 8601, "2026-11-25T16:38:51Z" (utc_timestamp_now)
};

struct LocationTrial {
  std::string participant;
  int trial = 0;  // counts from 1 across the whole study
  LocationMetaphor metaphor = LocationMetaphor::roughness;
  std::uint64_t seed = 0;  // the trial's data set (make_study_set(seed))
  double target_x_mm = 0, target_z_mm = 0;  // the intersection line (along y) in the x-z plane
  double mark_x_mm = 0, mark_y_mm = 0, mark_z_mm = 0;
  double error_mm = 0;  // distance from mark to target in the x-z plane
  double explore_s = 0;
  std::string time_utc;
};

extern const std::vector<std::string> kMatchingTrialHeader;
extern const std::vector<std::string> kLocationTrialHeader;

// The row's cells in header order; numbers with enough digits to read back exactly.
std::vector<std::string> to_cells(const MatchingTrial& trial);
std::vector<std::string> to_cells(const LocationTrial& trial);

template <class Row>
struct TrialTableResult {
  std::vector<Row> rows;  // empty when there is an error
  std::vector<Diagnostic> diagnostics;
  bool ok() const { return !has_errors(diagnostics); }
};

// A whole trial file of at most kMaxTrialFileBytes and kMaxTrialRows rows, checked line by line:
// the header, the cell count, every number and name, `correct` against presented == chosen,
// error_mm against the mark's x-z distance from the target (to 1e-9 relative), and trial numbers
// increasing per participant (a file may hold several participants; gaps are allowed). Every
// problem is `FILE:LINE: error: ...`. A last line without its line break (a crash mid-write) counts
// when it is a whole valid row and is otherwise left out with a warning; an empty file or a header
// cut short gives no rows and a warning. So a trial file can be read at any instant.
TrialTableResult<MatchingTrial> read_matching_trials(const std::filesystem::path& csv);
TrialTableResult<LocationTrial> read_location_trials(const std::filesystem::path& csv);

// The same readers on text already in memory (the trial log on open, tests, fuzzers).
TrialTableResult<MatchingTrial> parse_matching_trials(std::string_view text, const std::string& file_name);
TrialTableResult<LocationTrial> parse_location_trials(std::string_view text, const std::string& file_name);

// Which kind a trial file is, from its header line (`vimg study report` takes both). `unknown` for a
// file that cannot be read or whose first line is neither header.
enum class TrialFileKind { matching, location, unknown };
TrialFileKind trial_file_kind(const std::filesystem::path& csv);

}  // namespace vimg
