#pragma once
// Test helpers: vimg-player --study as a child process under SDL's dummy video and audio drivers,
// and the files a scripted matching test needs (a study of the shipped example images, responses
// from the participant's plan, a short rubbing gesture).
#include <sys/types.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "storage/study/study_file.hpp"
#include "storage/study/trial_table.hpp"
#include "study/trial_plan.hpp"

namespace vimg::study_test {

namespace fs = std::filesystem;

inline const fs::path kPlayer = fs::path(VIMG_BINARY_DIR) / "apps" / "vimg-player" / "vimg-player";
inline const fs::path kExample = fs::path(VIMG_SOURCE_DIR) / "assets" / "examples" / "matching";

struct Finished {
  int exit_code = -1;  // 128 + signal when killed by one
  bool signalled = false;
  std::string out, err;
};

// A running vimg-player (stdout and stderr to files in `capture`).
class Player {
 public:
  Player(const std::vector<std::string>& args, const fs::path& capture);
  ~Player();  // kills a child still running
  Player(const Player&) = delete;
  Player& operator=(const Player&) = delete;
  pid_t pid() const { return pid_; }
  void signal(int number) const;
  Finished wait();

 private:
  pid_t pid_ = -1;
  fs::path out_, err_;
};

// A test of its own folder: test_output/player_study/<test name>, emptied, with results/ in it.
class PlayerStudyTest : public ::testing::Test {
 protected:
  void SetUp() override;
  // --study STUDY --participant P --results <folder>/results in an 800x600 window at 3 px/mm, then `more`.
  std::vector<std::string> study_args(const fs::path& study, const std::string& participant,
                                      std::vector<std::string> more = {}) const;
  // A scripted run: the responses <folder>/R.csv, the gesture <folder>/G.csv, the output wav:<folder>/WAV.
  std::vector<std::string> scripted(const fs::path& study, const std::string& participant, const std::string& wav) const;
  fs::path root_;
};

// Runs to the end.
Finished run_player(const std::vector<std::string>& args, const fs::path& capture);

std::string read_text(const fs::path& path);
// Complete rows (lines ending in '\n') after the header; 0 when the file is not there.
std::size_t rows_in(const fs::path& trial_file);
// Polls (every 5 ms, at most `timeout_s`) until the trial file has at least `rows` rows or the
// player has ended. True when the rows are there.
bool wait_for_rows(const fs::path& trial_file, std::size_t rows, pid_t player, double timeout_s = 120.0);

// A study file in `dir` over copies of the example images: `sets` of the example's sets (1 or 2),
// the first `images` images of each, `repetitions` each.
fs::path write_study(const fs::path& dir, std::size_t sets, std::size_t images, int repetitions,
                     const std::string& extra_elements = "");
MatchingStudy load_study(const fs::path& study_file);

// Responses for every trial of the plan: the presented image, except every seventh trial which
// names the next image of the set (a confusion). Returns the chosen stems, trial by trial.
std::vector<std::string> write_responses(const fs::path& csv, const MatchingStudy& study,
                                         const std::vector<study::MatchingTrialPlan>& plan);

// One horizontal stroke across the 60 x 110 mm canvas at y = 62 mm lasting `seconds` (rows every
// 10 ms); its length is 50 mm.
void write_gesture(const fs::path& csv, double seconds);
inline constexpr double kGestureLengthMm = 50.0;

}  // namespace vimg::study_test
