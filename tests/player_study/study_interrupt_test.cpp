// A matching test interrupted (docs/player.md, "Matching test"): SIGKILL in the middle loses at
// most the trial under way and a second run continues with it, so that every trial is recorded
// exactly once; SIGTERM and SIGINT stop it at once with the trial file intact (exit 143, 130).
// The tests wait for states (rows in the trial file), never for fixed times: a scripted trial lasts
// as long as its gesture, so the player is still running when the rows appear.
#include <signal.h>

#include <gtest/gtest.h>

#include "tests/player_study/study_process.hpp"

namespace vimg::study_test {
namespace {

class PlayerStudyInterrupted : public PlayerStudyTest {
 protected:
  void SetUp() override {
    PlayerStudyTest::SetUp();
    study_file_ = kExample / "study.xml";
    study_ = load_study(study_file_);
  }
  std::vector<std::string> args(const std::string& participant, const std::string& wav) const {
    return scripted(study_file_, participant, wav);
  }
  fs::path study_file_;
  MatchingStudy study_;
};

TEST_F(PlayerStudyInterrupted, SigkillInTheMiddleThenARunAgainRecordsEveryTrialExactlyOnce) {
  const auto plan = study::plan_matching_trials(study_, "P10");
  const auto chosen = write_responses(root_ / "R.csv", study_, plan);
  write_gesture(root_ / "G.csv", 0.4);
  const fs::path trials = root_ / "results" / "P10.trials.csv";

  Player first(args("P10", "first.wav"), root_ / "first");
  ASSERT_TRUE(wait_for_rows(trials, 13, first.pid())) << read_text(root_ / "first" / "stderr");
  first.signal(SIGKILL);
  const Finished killed = first.wait();
  ASSERT_TRUE(killed.signalled);
  EXPECT_EQ(killed.exit_code, 128 + SIGKILL);
  const std::string before = read_text(trials);
  const std::size_t kept = rows_in(trials);
  EXPECT_GE(kept, 13u);
  EXPECT_LT(kept, 40u);

  const Finished second = run_player(args("P10", "second.wav"), root_ / "second");
  ASSERT_EQ(second.exit_code, 0) << second.err;
  EXPECT_NE(second.out.find(std::to_string(kept) + " done"), std::string::npos) << second.out;
  // The second run's first status line is the trial after the last one kept.
  EXPECT_EQ(second.out.find("vimg-player: trial " + std::to_string(kept) + " of 40"), std::string::npos) << second.out;
  EXPECT_NE(second.out.find("vimg-player: trial " + std::to_string(kept + 1) + " of 40"), std::string::npos);

  const std::string after = read_text(trials);
  EXPECT_EQ(after.substr(0, before.size()), before);  // the kept rows untouched
  const auto table = read_matching_trials(trials);
  ASSERT_TRUE(table.ok());
  ASSERT_EQ(table.rows.size(), 40u);
  for (std::size_t k = 1; k <= 40; ++k) {
    const MatchingTrial& row = table.rows[k - 1];
    EXPECT_EQ(row.trial, static_cast<int>(k));  // 1..40, each once, in order
    EXPECT_EQ(row.presented, study_image_name(study_.sets[plan[k - 1].set].images[plan[k - 1].image]));
    EXPECT_EQ(row.chosen, chosen[k - 1]);
  }
}

TEST_F(PlayerStudyInterrupted, SigtermStopsAtOnceWithTheTrialFileIntactAndExits143) {
  const auto plan = study::plan_matching_trials(study_, "P11");
  write_responses(root_ / "R.csv", study_, plan);
  write_gesture(root_ / "G.csv", 1.0);
  const fs::path trials = root_ / "results" / "P11.trials.csv";
  Player player(args("P11", "out.wav"), root_ / "run");
  ASSERT_TRUE(wait_for_rows(trials, 2, player.pid())) << read_text(root_ / "run" / "stderr");
  player.signal(SIGTERM);
  const Finished r = player.wait();
  EXPECT_FALSE(r.signalled);
  EXPECT_EQ(r.exit_code, 143) << r.err;
  const std::string text = read_text(trials);
  ASSERT_FALSE(text.empty());
  EXPECT_EQ(text.back(), '\n');  // no half-written row
  const auto table = read_matching_trials(trials);
  ASSERT_TRUE(table.ok());
  ASSERT_GE(table.rows.size(), 2u);
  ASSERT_LT(table.rows.size(), 40u);
  for (std::size_t k = 1; k <= table.rows.size(); ++k) EXPECT_EQ(table.rows[k - 1].trial, static_cast<int>(k));
  // As many status lines as rows: nothing recorded after the signal.
  std::size_t lines = 0;
  for (std::size_t at = r.out.find("vimg-player: trial "); at != std::string::npos; at = r.out.find("vimg-player: trial ", at + 1)) {
    ++lines;
  }
  EXPECT_EQ(lines, table.rows.size());
  // The output was put to rest and its file completed: the RIFF size is the file's.
  const std::string wav = read_text(root_ / "out.wav");
  ASSERT_GT(wav.size(), 8u);
  const auto riff = static_cast<std::size_t>(static_cast<unsigned char>(wav[4])) |
                    static_cast<std::size_t>(static_cast<unsigned char>(wav[5])) << 8 |
                    static_cast<std::size_t>(static_cast<unsigned char>(wav[6])) << 16 |
                    static_cast<std::size_t>(static_cast<unsigned char>(wav[7])) << 24;
  EXPECT_EQ(riff, wav.size() - 8);
}

TEST_F(PlayerStudyInterrupted, SigintExits130AndARunAgainContinues) {
  const auto plan = study::plan_matching_trials(study_, "P12");
  write_responses(root_ / "R.csv", study_, plan);
  write_gesture(root_ / "G.csv", 1.0);
  const fs::path trials = root_ / "results" / "P12.trials.csv";
  Player player(args("P12", "out.wav"), root_ / "run");
  ASSERT_TRUE(wait_for_rows(trials, 1, player.pid())) << read_text(root_ / "run" / "stderr");
  player.signal(SIGINT);
  const Finished r = player.wait();
  EXPECT_EQ(r.exit_code, 130) << r.err;
  const std::size_t kept = rows_in(trials);
  ASSERT_GE(kept, 1u);
  EXPECT_TRUE(read_matching_trials(trials).ok());
  // The next run starts at the next trial (its first status line names it).
  write_gesture(root_ / "G.csv", 0.02);
  const Finished again = run_player(args("P12", "again.wav"), root_ / "again");
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_EQ(again.out.find("vimg-player: trial " + std::to_string(kept) + " of 40 "), std::string::npos);
  EXPECT_EQ(rows_in(trials), 40u);
}

}  // namespace
}  // namespace vimg::study_test
