#pragma once
// The one trial log both studies write (the matching test in vimg-player, the location study in
// vimg-force): DIR/<participant>.<suffix>.csv, suffix "trials" for matching and "location" for
// location, a header line and then one line per trial (storage/study/trial_table.hpp).
//
// This is the one file the project writes without storage/atomic_file.hpp. An atomic write replaces
// a whole file at once; a log grows by one row per trial over an hour, and every row must be on disk
// the moment the trial ends, so that a crash or power loss loses at most the trial under way. So the
// log is appended in place (O_APPEND, one write() of one whole line, then fsync). The file is a
// valid trial table at every instant: the only damage a crash can leave is a torn last line, which
// every reader leaves out with a warning (storage/study/trial_text.hpp) and open() cuts off.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "storage/diagnostic.hpp"

namespace vimg {

struct TrialLogOptions {
  std::size_t total_trials = 0;  // trials in the whole study: a log holding this many is finished
  bool restart = false;          // keep an existing file aside and begin a new one
};

class TrialLog {
 public:
  // Opens or creates DIR/<participant>.<suffix>.csv (DIR must exist). `header` is
  // kMatchingTrialHeader or kLocationTrialHeader (storage/study/trial_table.hpp); the file is read
  // and checked as that kind's table, so what a log holds is always what read_matching_trials or
  // read_location_trials accept. A new file gets the header line, synced with the folder. An
  // existing file must hold trials 1..k in order, all of `participant`; a last line without its
  // line break (a crash mid-write) is cut off the file when it is not a whole row (the trial under
  // way is lost, nothing else) and reported as a warning; a whole row that only lost its line break
  // gets it back. While open, the log holds an exclusive flock() on the file: a second program
  // opening the same participant's log is refused.
  // Errors (the caller prints the diagnostics and exits 1): an invalid participant ID, a malformed
  // file, a wrong header, a symbolic link or other non-regular file, more rows than total_trials
  // (1..kMaxStudyTrials), a log another program holds, and a finished participant (completed ==
  // total_trials) without restart: "FILE: error: participant P has finished all N trials; --restart
  // keeps this file aside as P.SUFFIX.<UTC time>.csv and starts again". With restart, an existing
  // file (whatever it holds) is renamed aside to <participant>.<suffix>.<UTC stamp>.csv, the stamp
  // as 20261125T163851Z (".2", ".3", ... before ".csv" when that name exists: renameat2 with
  // RENAME_NOREPLACE, so an aside file is never overwritten) and a new one is begun.
  // Warnings (a torn line cut off, the file kept aside) come back with the log (warnings()).
  static std::variant<TrialLog, std::vector<Diagnostic>> open(const std::filesystem::path& dir,
                                                              const std::string& participant,
                                                              const std::string& suffix,
                                                              const std::vector<std::string>& header,
                                                              TrialLogOptions options);

  TrialLog(TrialLog&& other) noexcept;
  TrialLog& operator=(TrialLog&& other) noexcept;
  TrialLog(const TrialLog&) = delete;
  TrialLog& operator=(const TrialLog&) = delete;
  ~TrialLog();

  // Trials already in the file; the next trial is completed() + 1.
  std::size_t completed() const { return completed_; }
  const std::filesystem::path& path() const { return path_; }
  // What open() noted without refusing: a torn last line dropped, the old file kept aside.
  const std::vector<Diagnostic>& warnings() const { return warnings_; }

  // Writes the cells as one line with one write() and fsyncs the file before returning;
  // completed() then grows by one. The cells are checked first: as many as the header, none
  // holding a comma, double quote or control character, the participant's ID in the first and
  // completed() + 1 as the trial number, and not beyond total_trials. Returns the error text on
  // failure (the caller stops the study): a refused row writes nothing; a failed or short write is
  // cut off the file again and not counted; a failed sync after a whole write counts the row (it is
  // in the file, perhaps not yet on disk).
  std::optional<std::string> append(const std::vector<std::string>& cells);

 private:
  TrialLog(int fd, std::filesystem::path path, std::string participant, std::size_t trial_column, std::size_t columns,
           std::size_t total, std::size_t completed, std::uint64_t size_bytes, std::vector<Diagnostic> warnings);

  int fd_ = -1;  // open O_APPEND, holding an exclusive flock() while the log is open
  std::filesystem::path path_;
  std::string participant_;
  std::size_t trial_column_ = 0;  // where the trial number is in a row
  std::size_t columns_ = 0;
  std::size_t total_ = 0;
  std::size_t completed_ = 0;
  std::uint64_t size_bytes_ = 0;  // the file's length: a failed write is cut back to it
  std::vector<Diagnostic> warnings_;
};

// Participant IDs name files: [A-Za-z0-9_-]{1,64}; anything else is a usage error.
bool valid_participant_id(std::string_view id);

// The current time in UTC, ISO 8601 to the second: "2026-11-25T16:38:51Z".
std::string utc_timestamp_now();

}  // namespace vimg
