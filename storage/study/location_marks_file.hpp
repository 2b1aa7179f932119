#pragma once
// The simulated participant's presses for a location study on the simulated device
// (`vimg-force --study ... --device sim --marks M.csv`): per trial, the time after the trial's start
// at which button 0 goes down.
//
//   trial,time_s
//   1,0.75
//   2,1.4
//   ...
//
// Rows are the study's trials 1..N, in order, one each (N from the study file and its plan); times
// are seconds of the trial's own clock (the haptic loop's cycles, see location_study_port.hpp), in
// (0, kMaxProbePathDurationS]. Empty lines and lines starting with '#' are skipped. The file is read
// through the bounded reader (kMaxCsvFileBytes); every problem is `FILE:LINE: error: ...`.
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "storage/diagnostic.hpp"

namespace vimg {

struct MarkTimesResult {
  std::optional<std::vector<double>> times_s;  // trial k's time is (*times_s)[k - 1]; set only without errors
  std::vector<Diagnostic> diagnostics;
  bool ok() const { return times_s.has_value(); }
};

MarkTimesResult parse_mark_times(std::string_view text, const std::string& file_name, std::size_t total_trials);
MarkTimesResult load_mark_times(const std::filesystem::path& file, std::size_t total_trials);

}  // namespace vimg
