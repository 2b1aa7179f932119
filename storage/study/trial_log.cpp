// The append-synced trial log (storage/study/trial_log.hpp).
#include "storage/study/trial_log.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <utility>

#include "storage/diagnostic.hpp"
#include "storage/limits.hpp"
#include "storage/read_file.hpp"
#include "storage/study/trial_table.hpp"
#include "storage/study/trial_text.hpp"

namespace vimg {
namespace {

namespace fs = std::filesystem;

std::string errno_text() { return std::strerror(errno); }

// A rename that is a creation (and a folder's entries) survive a power loss once the folder is synced.
std::optional<std::string> sync_folder(const fs::path& dir) {
  const int fd = ::open(dir.empty() ? "." : dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return "cannot open the folder to sync it: " + errno_text();
  const bool ok = ::fsync(fd) == 0;
  const std::string why = ok ? "" : errno_text();
  ::close(fd);
  if (!ok) return "cannot sync the folder: " + why;
  return std::nullopt;
}

std::string utc_stamp(const char* format) {
  const std::time_t now = std::time(nullptr);
  std::tm tm{};
  ::gmtime_r(&now, &tm);
  char text[32];
  const std::size_t n = std::strftime(text, sizeof text, format, &tm);
  return std::string(text, n);
}

// Renames `from` to `to` unless `to` exists (never replacing it). EEXIST when it does.
int rename_no_replace(const fs::path& from, const fs::path& to) {
  if (::renameat2(AT_FDCWD, from.c_str(), AT_FDCWD, to.c_str(), RENAME_NOREPLACE) == 0) return 0;
  if (errno != EINVAL && errno != ENOSYS) return errno;
  // A file system without RENAME_NOREPLACE: a hard link fails on an existing name as well.
  if (::link(from.c_str(), to.c_str()) != 0) return errno;
  if (::unlink(from.c_str()) != 0) return errno;
  return 0;
}

// Moves `path` aside to <stem>.<UTC stamp>[.N].csv in its folder; the new name, or the error.
std::variant<fs::path, std::string> move_aside(const fs::path& path, const std::string& stem) {
  const std::string stamp = utc_stamp("%Y%m%dT%H%M%SZ");
  for (int n = 1; n <= 1000; ++n) {
    const fs::path aside =
        path.parent_path() / (stem + "." + stamp + (n == 1 ? std::string() : "." + std::to_string(n)) + ".csv");
    const int error = rename_no_replace(path, aside);
    if (error == 0) return aside;
    if (error != EEXIST) return "cannot keep the file aside as " + aside.filename().string() + ": " + std::strerror(error);
  }
  return std::string("cannot keep the file aside: 1000 names for this second are taken");
}

bool write_all_once(int fd, std::string_view bytes, std::string& error) {
  for (;;) {
    const ssize_t n = ::write(fd, bytes.data(), bytes.size());
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      error = "cannot write: " + errno_text();
      return false;
    }
    if (static_cast<std::size_t>(n) != bytes.size()) {
      error = "cannot write: only " + std::to_string(n) + " of " + std::to_string(bytes.size()) + " bytes written (disk full?)";
      return false;
    }
    return true;
  }
}

bool cell_safe(std::string_view cell) {
  for (const char c : cell) {
    const auto b = static_cast<unsigned char>(c);
    if (c == ',' || c == '"' || b < 0x20 || b == 0x7F) return false;
  }
  return true;
}

// What an existing log holds once checked: its rows, and how to make it end in a whole line.
struct Existing {
  std::size_t rows = 0;
  std::size_t keep_bytes = 0;    // the header and the whole rows; a torn last line is cut off after them
  bool add_line_break = false;   // the last whole row lost only its line break
  std::vector<Diagnostic> warnings;
};

// Reads the log's text as its kind's table and checks what a log must be beyond a table: one
// participant's trials 1..k in order, k at most the study's total. The diagnostics on failure.
template <class Row>
std::variant<Existing, std::vector<Diagnostic>> check_existing(trial_text::TrialText<Row> text, const std::string& file,
                                                               const std::string& participant, std::size_t total) {
  if (!text.table.ok()) return std::move(text.table.diagnostics);
  DiagnosticList list(file);
  const auto& rows = text.table.rows;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const int line = static_cast<int>(i) + 2;  // a table has no blank lines: row i is line i + 2
    if (rows[i].participant != participant) {
      list.error(line, "a row of participant '" + rows[i].participant + "' in the trial log of participant '" + participant + "'");
    } else if (static_cast<std::size_t>(rows[i].trial) != i + 1) {
      list.error(line, "trial " + std::to_string(rows[i].trial) + " where the log holds trial " + std::to_string(i + 1) +
                           " (a trial log holds trials 1, 2, 3, ... in order)");
    } else if (i + 1 > total) {
      list.error(line, "trial " + std::to_string(i + 1) + " is beyond the study's " + std::to_string(total) +
                           " trials (was the study file changed?)");
    } else {
      continue;
    }
    return list.take();
  }
  return Existing{rows.size(), text.complete_bytes, text.missing_line_break, std::move(text.table.diagnostics)};
}

}  // namespace

TrialLog::TrialLog(int fd, std::filesystem::path path, std::string participant, std::size_t trial_column,
                   std::size_t columns, std::size_t total, std::size_t completed, std::uint64_t size_bytes,
                   std::vector<Diagnostic> warnings)
    : fd_(fd), path_(std::move(path)), participant_(std::move(participant)), trial_column_(trial_column),
      columns_(columns), total_(total), completed_(completed), size_bytes_(size_bytes), warnings_(std::move(warnings)) {}

TrialLog::TrialLog(TrialLog&& other) noexcept { *this = std::move(other); }

TrialLog& TrialLog::operator=(TrialLog&& other) noexcept {
  if (this != &other) {
    if (fd_ >= 0) ::close(fd_);
    fd_ = std::exchange(other.fd_, -1);
    path_ = std::move(other.path_);
    participant_ = std::move(other.participant_);
    trial_column_ = other.trial_column_;
    columns_ = other.columns_;
    total_ = other.total_;
    completed_ = other.completed_;
    size_bytes_ = other.size_bytes_;
    warnings_ = std::move(other.warnings_);
  }
  return *this;
}

TrialLog::~TrialLog() {
  if (fd_ >= 0) ::close(fd_);  // also releases the lock
}

std::variant<TrialLog, std::vector<Diagnostic>> TrialLog::open(const fs::path& dir, const std::string& participant,
                                                               const std::string& suffix,
                                                               const std::vector<std::string>& header,
                                                               TrialLogOptions options) {
  const bool matching = header == kMatchingTrialHeader;
  if (!valid_participant_id(participant)) {
    DiagnosticList list(dir.string());
    list.error(0, "participant ID '" + escape_input(participant) + "' is not valid: 1 to 64 of A-Z a-z 0-9 _ - (it names the trial file)");
    return list.take();
  }
  const std::string stem = participant + "." + suffix;
  const fs::path path = dir / (stem + ".csv");
  DiagnosticList list(path.string());
  const auto failed = [&](std::string_view message) {
    list.error(0, message);
    return std::variant<TrialLog, std::vector<Diagnostic>>(list.take());
  };
  if (suffix.empty() || suffix.size() > 32 || suffix.find_first_not_of("abcdefghijklmnopqrstuvwxyz") != std::string::npos) {
    return failed("trial log suffix '" + escape_input(suffix) + "' is not 1 to 32 of a-z");
  }
  if (!matching && header != kLocationTrialHeader) return failed("a trial log takes the matching or the location trial header");
  if (options.total_trials < 1 || options.total_trials > kMaxStudyTrials) {
    return failed("a study has 1 to " + std::to_string(kMaxStudyTrials) + " trials, not " + std::to_string(options.total_trials));
  }
  const std::size_t trial_column = matching ? 2 : 1;
  std::vector<Diagnostic> warnings;

  int fd = ::open(path.c_str(), O_RDWR | O_APPEND | O_NOFOLLOW | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
  if (fd < 0 && errno != ENOENT) {
    if (errno == ELOOP) return failed("is a symbolic link (a trial log is a file of its own)");
    return failed("cannot open: " + errno_text());
  }
  if (fd >= 0) {
    struct stat st {};
    if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
      ::close(fd);
      return failed("is not a regular file");
    }
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
      ::close(fd);
      return failed("another program is writing this trial log (is participant " + participant + "'s session running?)");
    }
    if (options.restart) {
      const auto aside = move_aside(path, stem);
      ::close(fd);
      if (const auto* why = std::get_if<std::string>(&aside)) return failed(*why);
      if (const auto sync = sync_folder(dir)) return failed(*sync);
      DiagnosticList note(path.string());
      note.warning(0, "--restart: the earlier trials are kept aside in " + std::get<fs::path>(aside).string());
      append_diagnostics(warnings, note.take());
      fd = -1;
    }
  }
  if (fd >= 0) {
    const FileReadResult read = read_open_file(fd, kMaxTrialFileBytes);
    if (!read.bytes) {
      ::close(fd);
      return failed(read.error);
    }
    auto checked = matching ? check_existing(trial_text::parse_matching(*read.bytes, path.string()), path.string(),
                                             participant, options.total_trials)
                            : check_existing(trial_text::parse_location(*read.bytes, path.string()), path.string(),
                                             participant, options.total_trials);
    if (auto* problems = std::get_if<std::vector<Diagnostic>>(&checked)) {
      ::close(fd);
      return std::move(*problems);
    }
    Existing* existing = &std::get<Existing>(checked);
    if (existing->rows == options.total_trials) {
      ::close(fd);
      return failed("participant " + participant + " has finished all " + std::to_string(options.total_trials) +
                    " trials; --restart keeps this file aside as " + stem + ".<UTC time>.csv and starts again");
    }
    // Only a torn last line (or the header cut short) can differ from what was appended whole.
    std::string problem;
    std::uint64_t size = existing->keep_bytes;
    if (existing->keep_bytes < read.bytes->size() && ::ftruncate(fd, static_cast<off_t>(existing->keep_bytes)) != 0) {
      problem = "cannot cut off the torn last line: " + errno_text();
    }
    if (problem.empty() && existing->keep_bytes == 0 && !write_all_once(fd, trial_text::header_line(header) + "\n", problem)) {
      problem = "cannot write the header: " + problem;
    }
    if (problem.empty() && existing->keep_bytes == 0) size = trial_text::header_line(header).size() + 1;
    if (problem.empty() && existing->add_line_break && existing->keep_bytes > 0) {
      if (write_all_once(fd, "\n", problem)) ++size;
    }
    if (problem.empty() && size != read.bytes->size() && ::fsync(fd) != 0) problem = "cannot sync: " + errno_text();
    if (!problem.empty()) {
      ::close(fd);
      return failed(problem);
    }
    append_diagnostics(warnings, std::move(existing->warnings));
    return TrialLog(fd, path, participant, trial_column, header.size(), options.total_trials, existing->rows, size,
                    std::move(warnings));
  }

  fd = ::open(path.c_str(), O_RDWR | O_APPEND | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
  if (fd < 0) return failed("cannot create: " + errno_text());
  std::string problem;
  const std::string first = trial_text::header_line(header) + "\n";
  if (::flock(fd, LOCK_EX | LOCK_NB) != 0) problem = "another program is writing this trial log";
  if (problem.empty() && !write_all_once(fd, first, problem)) problem = "cannot write the header: " + problem;
  if (problem.empty() && ::fsync(fd) != 0) problem = "cannot sync: " + errno_text();
  if (problem.empty()) {
    if (const auto sync = sync_folder(dir)) problem = *sync;
  }
  if (!problem.empty()) {
    ::close(fd);
    return failed(problem);
  }
  return TrialLog(fd, path, participant, trial_column, header.size(), options.total_trials, 0, first.size(),
                  std::move(warnings));
}

std::optional<std::string> TrialLog::append(const std::vector<std::string>& cells) {
  const std::string where = path_.string() + ": ";
  if (fd_ < 0) return where + "the trial log is not open";
  if (cells.size() != columns_) {
    return where + "a row of " + std::to_string(cells.size()) + " cells, the log has " + std::to_string(columns_) + " columns";
  }
  if (completed_ >= total_) return where + "all " + std::to_string(total_) + " trials of the study are in the log";
  if (cells[0] != participant_) return where + "a row of participant '" + escape_input(cells[0]) + "' in the log of '" + participant_ + "'";
  if (cells[trial_column_] != std::to_string(completed_ + 1)) {
    return where + "the next trial is " + std::to_string(completed_ + 1) + ", not '" + escape_input(cells[trial_column_]) + "'";
  }
  std::string line;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    if (!cell_safe(cells[i])) return where + "cell '" + escape_input(cells[i]) + "' holds a comma, a quote or a control character";
    if (i > 0) line += ',';
    line += cells[i];
  }
  line += '\n';
  std::string problem;
  if (!write_all_once(fd_, line, problem)) {
    // Whatever part of the line reached the file is cut off again, so the file stays a table.
    if (::ftruncate(fd_, static_cast<off_t>(size_bytes_)) != 0) problem += "; cannot cut off the partial line: " + errno_text();
    return where + problem;
  }
  // The row is in the file: it counts, whether or not the sync succeeds (a failed sync leaves it
  // perhaps not on disk; the caller stops the study, and the next open reads what the disk holds).
  size_bytes_ += line.size();
  ++completed_;
  if (::fsync(fd_) != 0) return where + "cannot sync: " + errno_text();
  return std::nullopt;
}

std::string utc_timestamp_now() { return utc_stamp("%Y-%m-%dT%H:%M:%SZ"); }

}  // namespace vimg
