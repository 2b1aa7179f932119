// The trial log (storage/study/trial_log.hpp): append and sync one row per trial, resume after a
// killed writer without losing or repeating a trial, drop a torn last line, refuse a finished
// participant, and keep the old file aside on --restart without ever overwriting an aside file.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <ctime>
#include <filesystem>
#include <string>

#include "storage/limits.hpp"
#include "storage/study/trial_log.hpp"
#include "storage/study/trial_table.hpp"
#include "tests/storage/storage_test_support.hpp"

namespace vimg {
namespace {

namespace fs = std::filesystem;

const std::string kHeader = "participant,set,trial,presented,chosen,correct,rub_s,response_s,path_mm,time_utc\n";

std::string messages(const std::vector<Diagnostic>& diagnostics) {
  std::string all;
  for (const auto& d : diagnostics) all += d.to_string() + "\n";
  return all;
}

MatchingTrial trial(const std::string& participant, int number) {
  MatchingTrial t;
  t.participant = participant;
  t.set = "shapes";
  t.trial = number;
  t.presented = number % 3 ? "dot" : "line";
  t.chosen = "dot";
  t.correct = t.presented == t.chosen;
  t.rub_s = 0.1 * number;
  t.response_s = 1.5;
  t.path_mm = 12.25;
  t.time_utc = "2026-11-25T16:38:51Z";
  return t;
}

std::string row(const std::string& participant, int number) {
  std::string line;
  for (const auto& c : to_cells(trial(participant, number))) line += (line.empty() ? "" : ",") + c;
  return line + "\n";
}

std::variant<TrialLog, std::vector<Diagnostic>> open_log(const fs::path& dir, std::size_t total, bool restart = false,
                                                         const std::string& participant = "P01") {
  return TrialLog::open(dir, participant, "trials", kMatchingTrialHeader, TrialLogOptions{total, restart});
}

TrialLog opened(std::variant<TrialLog, std::vector<Diagnostic>> v) {
  if (auto* problems = std::get_if<std::vector<Diagnostic>>(&v)) {
    ADD_FAILURE() << messages(*problems);
    std::abort();
  }
  return std::move(std::get<TrialLog>(v));
}

std::string refusal(std::variant<TrialLog, std::vector<Diagnostic>> v) {
  if (std::holds_alternative<TrialLog>(v)) return "opened";
  return messages(std::get<std::vector<Diagnostic>>(v));
}

TEST(TrialLog, NewLogHasTheHeaderAndEachAppendIsOneWholeSyncedRow) {
  test::TempDir dir("log_new");
  TrialLog log = opened(open_log(dir.path(), 5));
  EXPECT_EQ(log.path(), dir / "P01.trials.csv");
  EXPECT_EQ(log.completed(), 0u);
  EXPECT_TRUE(log.warnings().empty());
  EXPECT_EQ(test::read_text_file(log.path()), kHeader);
  for (int k = 1; k <= 3; ++k) {
    ASSERT_EQ(log.append(to_cells(trial("P01", k))), std::nullopt);
    EXPECT_EQ(log.completed(), static_cast<std::size_t>(k));
    // The file is a whole table after every append (what the report would read at that instant).
    const auto table = read_matching_trials(log.path());
    ASSERT_TRUE(table.ok());
    EXPECT_EQ(table.rows.size(), static_cast<std::size_t>(k));
  }
  EXPECT_EQ(test::read_text_file(log.path()), kHeader + row("P01", 1) + row("P01", 2) + row("P01", 3));
}

TEST(TrialLog, AppendRefusesRowsThatWouldBreakTheTable) {
  test::TempDir dir("log_refuse");
  TrialLog log = opened(open_log(dir.path(), 2));
  const std::string where = (dir / "P01.trials.csv").string() + ": ";
  EXPECT_EQ(log.append(to_cells(trial("P01", 2))), where + "the next trial is 1, not '2'");
  EXPECT_EQ(log.append(to_cells(trial("P02", 1))), where + "a row of participant 'P02' in the log of 'P01'");
  auto cells = to_cells(trial("P01", 1));
  cells[1] = "a,b";
  EXPECT_EQ(log.append(cells), where + "cell 'a,b' holds a comma, a quote or a control character");
  cells.pop_back();
  EXPECT_EQ(log.append(cells), where + "a row of 9 cells, the log has 10 columns");
  EXPECT_EQ(test::read_text_file(log.path()), kHeader);
  ASSERT_EQ(log.append(to_cells(trial("P01", 1))), std::nullopt);
  ASSERT_EQ(log.append(to_cells(trial("P01", 2))), std::nullopt);
  EXPECT_EQ(log.append(to_cells(trial("P01", 3))), where + "all 2 trials of the study are in the log");
}

TEST(TrialLog, ResumesAtTheNextTrial) {
  test::TempDir dir("log_resume");
  {
    TrialLog log = opened(open_log(dir.path(), 4));
    ASSERT_EQ(log.append(to_cells(trial("P01", 1))), std::nullopt);
    ASSERT_EQ(log.append(to_cells(trial("P01", 2))), std::nullopt);
  }
  TrialLog log = opened(open_log(dir.path(), 4));
  EXPECT_EQ(log.completed(), 2u);
  ASSERT_EQ(log.append(to_cells(trial("P01", 3))), std::nullopt);
  EXPECT_EQ(test::read_text_file(log.path()), kHeader + row("P01", 1) + row("P01", 2) + row("P01", 3));
}

// A writer killed at a random moment (SIGKILL while it appends and syncs as fast as it can, so
// mostly inside write() or fsync()), then a new writer that continues: trials 1..n exactly once,
// in order, with every trial the killed writer had synced. The writer stops 3 rows short of the
// study's end and waits there, so however late the kill lands (a test process descheduled for
// seconds), the log it leaves is unfinished and takes the 3 rows appended after it. (Running to
// the end, a writer on tmpfs, where fsync costs nothing, finished all its trials during a 5 s
// stall before the kill, and the resumed log, refused as finished, aborted the binary.)
TEST(TrialLog, KilledWriterResumesWithoutLosingOrRepeatingATrial) {
  test::TempDir dir("log_kill");
  constexpr std::size_t kTotal = kMaxStudyTrials;
  for (const std::size_t kill_after : {1u, 37u, 120u}) {
    SCOPED_TRACE("killed after " + std::to_string(kill_after) + " rows");
    fs::remove(dir / "P01.trials.csv");
    int pipe_fds[2];
    ASSERT_EQ(::pipe(pipe_fds), 0);
    const pid_t parent = ::getpid();
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
      ::prctl(PR_SET_PDEATHSIG, SIGKILL);  // never outlives a test that stopped before the kill
      if (::getppid() != parent) ::_exit(6);
      ::close(pipe_fds[0]);
      auto v = open_log(dir.path(), kTotal);
      if (!std::holds_alternative<TrialLog>(v)) ::_exit(3);
      TrialLog& log = std::get<TrialLog>(v);
      for (int k = 1; k <= static_cast<int>(kTotal) - 3; ++k) {
        if (log.append(to_cells(trial("P01", k)))) ::_exit(4);
        const char done = 'r';
        if (::write(pipe_fds[1], &done, 1) != 1) ::_exit(5);  // one byte per row on disk
      }
      for (;;) ::pause();  // all written: wait for the kill
    }
    ::close(pipe_fds[1]);
    // Wait on the state: the child reports each row once it is synced.
    std::size_t reported = 0;
    char buffer[64];
    while (reported < kill_after) {
      const ssize_t n = ::read(pipe_fds[0], buffer, std::min(sizeof buffer, kill_after - reported));
      ASSERT_GT(n, 0) << "the writer ended before " << kill_after << " rows";
      reported += static_cast<std::size_t>(n);
    }
    ASSERT_EQ(::kill(child, SIGKILL), 0);
    int status = 0;
    ASSERT_EQ(::waitpid(child, &status, 0), child);
    ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL) << "writer exited with " << status;
    ::close(pipe_fds[0]);

    TrialLog log = opened(open_log(dir.path(), kTotal));
    EXPECT_GE(log.completed(), kill_after);  // nothing synced is lost
    EXPECT_TRUE(log.warnings().empty()) << messages(log.warnings());
    EXPECT_LE(log.completed(), kTotal - 3);
    const std::size_t resumed = log.completed();
    for (std::size_t k = resumed + 1; k <= resumed + 3; ++k) {
      ASSERT_EQ(log.append(to_cells(trial("P01", static_cast<int>(k)))), std::nullopt);
    }
    const auto table = read_matching_trials(log.path());
    ASSERT_TRUE(table.ok()) << messages(table.diagnostics);
    ASSERT_EQ(table.rows.size(), resumed + 3);
    for (std::size_t i = 0; i < table.rows.size(); ++i) {
      ASSERT_EQ(table.rows[i].trial, static_cast<int>(i + 1));
      ASSERT_EQ(to_cells(table.rows[i]), to_cells(trial("P01", static_cast<int>(i + 1))));
    }
  }
}

TEST(TrialLog, TornLastLineIsCutOffWithAWarning) {
  test::TempDir dir("log_torn");
  const fs::path file = dir / "P01.trials.csv";
  const std::string whole = kHeader + row("P01", 1) + row("P01", 2);
  test::write_text_file(file, whole + row("P01", 3).substr(0, 17));
  TrialLog log = opened(open_log(dir.path(), 10));
  EXPECT_EQ(log.completed(), 2u);
  EXPECT_EQ(messages(log.warnings()),
            file.string() + ":4: warning: the last line is cut short (no line break): the trial under way when the file was cut, left out\n");
  EXPECT_EQ(test::read_text_file(file), whole);
  ASSERT_EQ(log.append(to_cells(trial("P01", 3))), std::nullopt);
  EXPECT_EQ(test::read_text_file(file), whole + row("P01", 3));
}

TEST(TrialLog, WholeRowThatLostOnlyItsLineBreakCounts) {
  test::TempDir dir("log_no_break");
  const fs::path file = dir / "P01.trials.csv";
  std::string two = kHeader + row("P01", 1) + row("P01", 2);
  two.pop_back();
  test::write_text_file(file, two);
  TrialLog log = opened(open_log(dir.path(), 10));
  EXPECT_EQ(log.completed(), 2u);
  ASSERT_EQ(log.append(to_cells(trial("P01", 3))), std::nullopt);
  EXPECT_EQ(test::read_text_file(file), kHeader + row("P01", 1) + row("P01", 2) + row("P01", 3));
}

TEST(TrialLog, HeaderCutShortBeginsAgain) {
  test::TempDir dir("log_cut_header");
  const fs::path file = dir / "P01.trials.csv";
  for (const std::string& start : {std::string(), kHeader.substr(0, 30)}) {
    test::write_text_file(file, start);
    TrialLog log = opened(open_log(dir.path(), 10));
    EXPECT_EQ(log.completed(), 0u);
    EXPECT_EQ(log.warnings().size(), 1u);
    EXPECT_EQ(test::read_text_file(file), kHeader);
  }
}

TEST(TrialLog, RefusesWhatIsNotItsLog) {
  test::TempDir dir("log_bad");
  const fs::path file = dir / "P01.trials.csv";
  const std::string f = file.string();
  test::write_text_file(file, kHeader + row("P01", 1) + row("P02", 2));
  EXPECT_EQ(refusal(open_log(dir.path(), 10)), f + ":3: error: a row of participant 'P02' in the trial log of participant 'P01'\n");
  test::write_text_file(file, kHeader + row("P01", 1) + row("P01", 3));
  EXPECT_EQ(refusal(open_log(dir.path(), 10)),
            f + ":3: error: trial 3 where the log holds trial 2 (a trial log holds trials 1, 2, 3, ... in order)\n");
  test::write_text_file(file, kHeader + row("P01", 1) + row("P01", 2) + row("P01", 3));
  EXPECT_EQ(refusal(open_log(dir.path(), 2)), f + ":4: error: trial 3 is beyond the study's 2 trials (was the study file changed?)\n");
  test::write_text_file(file, "time_s,finger,x_mm,y_mm,pressure,phase\n");
  EXPECT_EQ(refusal(open_log(dir.path(), 2)),
            f + ":1: error: expected the header 'participant,set,trial,presented,chosen,correct,rub_s,response_s,path_mm,time_utc'\n");
  fs::remove(file);
  fs::create_symlink("elsewhere.csv", file);
  EXPECT_EQ(refusal(open_log(dir.path(), 2)), f + ": error: is a symbolic link (a trial log is a file of its own)\n");
  EXPECT_EQ(refusal(open_log(dir.path(), 2, false, "../P01")),
            dir.path().string() + ": error: participant ID '../P01' is not valid: 1 to 64 of A-Z a-z 0-9 _ - (it names the trial file)\n");
  EXPECT_EQ(refusal(open_log(dir / "missing", 2)), (dir / "missing" / "P01.trials.csv").string() + ": error: cannot create: No such file or directory\n");
}

TEST(TrialLog, OneWriterAtATime) {
  test::TempDir dir("log_lock");
  TrialLog first = opened(open_log(dir.path(), 5));
  EXPECT_EQ(refusal(open_log(dir.path(), 5)),
            first.path().string() + ": error: another program is writing this trial log (is participant P01's session running?)\n");
  TrialLog moved = std::move(first);  // the lock moves with the log
  EXPECT_NE(refusal(open_log(dir.path(), 5)), "opened");
}

TEST(TrialLog, FinishedParticipantIsRefusedUnlessRestarted) {
  test::TempDir dir("log_finished");
  const fs::path file = dir / "P01.trials.csv";
  {
    TrialLog log = opened(open_log(dir.path(), 2));
    ASSERT_EQ(log.append(to_cells(trial("P01", 1))), std::nullopt);
    ASSERT_EQ(log.append(to_cells(trial("P01", 2))), std::nullopt);
  }
  const std::string finished = test::read_text_file(file);
  EXPECT_EQ(refusal(open_log(dir.path(), 2)),
            file.string() + ": error: participant P01 has finished all 2 trials; --restart keeps this file aside as "
                            "P01.trials.<UTC time>.csv and starts again\n");
  EXPECT_EQ(test::read_text_file(file), finished);

  // The aside name of every second from now to 5 minutes on is taken already: whichever second
  // the restart below falls in (the test may be descheduled for a while), its name is taken, and
  // the planted files must survive untouched.
  constexpr std::time_t kPlantedS = 300;
  const std::time_t start = std::time(nullptr);
  std::vector<fs::path> planted;
  for (std::time_t t = start; t <= start + kPlantedS; ++t) {
    std::tm tm{};
    ::gmtime_r(&t, &tm);
    char stamp[32];
    std::strftime(stamp, sizeof stamp, "%Y%m%dT%H%M%SZ", &tm);
    planted.push_back(dir / ("P01.trials." + std::string(stamp) + ".csv"));
    test::write_text_file(planted.back(), "planted " + std::string(stamp));
  }
  TrialLog log = opened(open_log(dir.path(), 2, true));
  ASSERT_LE(std::time(nullptr), start + kPlantedS) << "the restart took longer than the planted names cover";
  EXPECT_EQ(log.completed(), 0u);
  EXPECT_EQ(test::read_text_file(file), kHeader);
  for (const auto& p : planted) EXPECT_EQ(test::read_text_file(p), "planted " + p.stem().extension().string().substr(1));
  // The old trials are in exactly one new file, named in the warning.
  std::vector<fs::path> aside;
  for (const auto& entry : fs::directory_iterator(dir.path())) {
    if (entry.path() != file && std::find(planted.begin(), planted.end(), entry.path()) == planted.end()) aside.push_back(entry.path());
  }
  ASSERT_EQ(aside.size(), 1u);
  EXPECT_EQ(test::read_text_file(aside[0]), finished);
  // The name of a planted second with ".2" before ".csv".
  const std::string name = aside[0].filename().string();
  ASSERT_TRUE(name.ends_with(".2.csv")) << aside[0];
  const fs::path taken = dir / (name.substr(0, name.size() - 6) + ".csv");
  EXPECT_NE(std::find(planted.begin(), planted.end(), taken), planted.end()) << aside[0];
  EXPECT_EQ(messages(log.warnings()), file.string() + ": warning: --restart: the earlier trials are kept aside in " + aside[0].string() + "\n");
}

TEST(TrialLog, ParticipantIds) {
  EXPECT_TRUE(valid_participant_id("P01"));
  EXPECT_TRUE(valid_participant_id("a_b-C9"));
  EXPECT_TRUE(valid_participant_id(std::string(64, 'x')));
  EXPECT_FALSE(valid_participant_id(std::string(65, 'x')));
  EXPECT_FALSE(valid_participant_id(""));
  EXPECT_FALSE(valid_participant_id("P 1"));
  EXPECT_FALSE(valid_participant_id("../x"));
  EXPECT_FALSE(valid_participant_id("P1.csv"));
  EXPECT_FALSE(valid_participant_id("Pé"));
}

TEST(TrialLog, UtcTimestampIsIso8601) {
  const std::string now = utc_timestamp_now();
  const std::string text = kHeader + "P1,s,1,a,a,1,1,1,1," + now + "\n";
  EXPECT_TRUE(parse_matching_trials(text, "m.csv").ok()) << now;
}

}  // namespace
}  // namespace vimg
