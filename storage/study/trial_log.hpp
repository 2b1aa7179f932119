#pragma once
// The one trial log both studies write (the matching test in vimg-player, the location study in
// vimg-force): DIR/<participant>.<suffix>.csv, suffix "trials" for matching and "location" for
// location, a header line and then one line per trial (storage/study/trial_table.hpp).
//
// This is the one file the project writes without storage/atomic_file.hpp. An atomic write replaces
// a whole file at once; a log grows by one row per trial over an hour, and every row must be on disk
// the moment the trial ends, so that a crash or power loss loses at most the trial under way. So the
// log is appended in place (O_APPEND, one write() of one whole line, then fsync), which keeps the
// file a valid trial table at every instant except for a torn last line, which open() drops.
#include <cstddef>
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
  // Opens or creates DIR/<participant>.<suffix>.csv (DIR must exist). A new file gets the header
  // line, synced with the folder. An existing file is read as a trial table (`header` must be its
  // first line; rows must be trials 1..k in order, all of `participant`); a last line without its
  // line break (a crash mid-write) is cut off the file and reported as a warning diagnostic (the
  // trial under way is lost, nothing else).
  // Errors (the caller prints the diagnostics and exits 1): an invalid participant ID, a malformed
  // file, a wrong header, more rows than total_trials, and a finished participant (completed ==
  // total_trials) without restart: "FILE: error: participant P has finished all N trials; --restart
  // keeps this file aside as FILE.<UTC stamp>.csv and starts again". With restart, an existing
  // file is renamed aside to <participant>.<suffix>.<UTC stamp>.csv (".2", ".3", ... added before
  // ".csv" when that name exists; never overwritten, whatever the file held) and a new one begun.
  // Warnings come back with the log (warnings()).
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

  // Writes the cells (as many as the header, none holding a comma, quote or line break) as one line
  // with one write() and fsyncs the file before returning; completed() then grows by one. Returns
  // the error text on failure (the row is then not counted; the caller stops the study).
  std::optional<std::string> append(const std::vector<std::string>& cells);

 private:
  TrialLog(int fd, std::filesystem::path path, std::size_t columns, std::size_t completed,
           std::vector<Diagnostic> warnings);

  int fd_ = -1;
  std::filesystem::path path_;
  std::size_t columns_ = 0;
  std::size_t completed_ = 0;
  std::vector<Diagnostic> warnings_;
};

// Participant IDs name files: [A-Za-z0-9_-]{1,64}; anything else is a usage error.
bool valid_participant_id(std::string_view id);

// The current time in UTC, ISO 8601 to the second: "2026-11-25T16:38:51Z".
std::string utc_timestamp_now();

}  // namespace vimg
