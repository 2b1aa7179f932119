#include "tests/player_study/study_process.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <fstream>
#include <sstream>
#include <thread>

#include "tests/child_process.hpp"

namespace vimg::study_test {

namespace {

const std::vector<std::pair<std::string, std::vector<std::string>>> kSets{
    {"complexity", {"dot", "line", "surface", "house"}},
    {"same-complexity", {"surface_top", "surface_bottom", "line_left", "line_right"}}};

}  // namespace

Player::Player(const std::vector<std::string>& args, const fs::path& capture)
    : out_(capture / "stdout"), err_(capture / "stderr") {
  fs::create_directories(capture);
  test::ChildSpec spec;
  spec.argv = {kPlayer.string()};
  spec.argv.insert(spec.argv.end(), args.begin(), args.end());
  spec.env = {{"SDL_VIDEODRIVER", "dummy"}, {"SDL_AUDIODRIVER", "dummy"}};
  spec.stdout_file = out_;
  spec.stderr_file = err_;
  pid_ = test::spawn_child(spec);
  EXPECT_GT(pid_, 0) << "fork failed: " << std::strerror(errno);
}

Player::~Player() {
  if (test::signal_child(pid_, SIGKILL)) test::reap_child(pid_);
}

void Player::signal(int number) const {
  test::signal_child(pid_, number);
}

Finished Player::wait() {
  Finished f;
  int status = 0;
  if (pid_ > 0 && ::waitpid(pid_, &status, 0) == pid_) {
    f.signalled = WIFSIGNALED(status);
    f.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  }
  pid_ = -1;
  f.out = read_text(out_);
  f.err = read_text(err_);
  return f;
}

void PlayerStudyTest::SetUp() {
  root_ = fs::path(VIMG_BINARY_DIR) / "test_output" / "player_study" /
          ::testing::UnitTest::GetInstance()->current_test_info()->name();
  fs::remove_all(root_);
  fs::create_directories(root_ / "results");
}

std::vector<std::string> PlayerStudyTest::study_args(const fs::path& study, const std::string& participant,
                                                     std::vector<std::string> more) const {
  std::vector<std::string> args{"--study", study.string(), "--participant", participant, "--results",
                                (root_ / "results").string(), "--window", "800x600", "--px-per-mm", "3"};
  args.insert(args.end(), more.begin(), more.end());
  return args;
}

std::vector<std::string> PlayerStudyTest::scripted(const fs::path& study, const std::string& participant,
                                                   const std::string& wav) const {
  return study_args(study, participant,
                    {"--responses", (root_ / "R.csv").string(), "--gesture", (root_ / "G.csv").string(), "--output",
                     "wav:" + (root_ / wav).string()});
}

Finished run_player(const std::vector<std::string>& args, const fs::path& capture) {
  Player player(args, capture);
  return player.wait();
}

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::size_t rows_in(const fs::path& trial_file) {
  const std::string text = read_text(trial_file);
  std::size_t lines = 0;
  for (char c : text) lines += c == '\n' ? 1 : 0;
  return lines == 0 ? 0 : lines - 1;
}

bool wait_for_rows(const fs::path& trial_file, std::size_t rows, pid_t player, double timeout_s) {
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  while (std::chrono::steady_clock::now() < give_up) {
    if (rows_in(trial_file) >= rows) return true;
    int status = 0;
    if (::waitpid(player, &status, WNOHANG) == player) return false;  // ended first (and reaped: the test fails)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return false;
}

fs::path write_study(const fs::path& dir, std::size_t sets, std::size_t images, int repetitions,
                     const std::string& extra_elements) {
  fs::create_directories(dir);
  std::ostringstream xml;
  xml << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<matchingStudy version=\"1\" seed=\"2024\" repetitions=\""
      << repetitions << "\" trainingMinutes=\"3\">\n" << extra_elements;
  for (std::size_t s = 0; s < sets; ++s) {
    xml << "  <set name=\"" << kSets[s].first << "\">\n";
    for (std::size_t i = 0; i < images; ++i) {
      const std::string file = kSets[s].second[i] + ".vimg";
      fs::copy_file(kExample / file, dir / file, fs::copy_options::overwrite_existing);
      xml << "    <image file=\"" << file << "\"/>\n";
    }
    xml << "  </set>\n";
  }
  xml << "</matchingStudy>\n";
  std::ofstream(dir / "study.xml") << xml.str();
  return dir / "study.xml";
}

MatchingStudy load_study(const fs::path& study_file) {
  auto loaded = load_matching_study(study_file);
  for (const auto& d : loaded.diagnostics) ADD_FAILURE() << d.to_string();
  return loaded.study.value_or(MatchingStudy{});
}

std::vector<std::string> write_responses(const fs::path& csv, const MatchingStudy& study,
                                         const std::vector<study::MatchingTrialPlan>& plan) {
  std::vector<std::string> chosen;
  std::ofstream out(csv);
  out << "trial,chosen\n";
  for (std::size_t k = 1; k <= plan.size(); ++k) {
    const auto& images = study.sets[plan[k - 1].set].images;
    const std::size_t image = k % 7 == 0 ? (plan[k - 1].image + 1) % images.size() : plan[k - 1].image;
    chosen.push_back(study_image_name(images[image]));
    out << k << "," << chosen.back() << "\n";
  }
  return chosen;
}

void write_gesture(const fs::path& csv, double seconds) {
  std::ofstream out(csv);
  out << "time_s,finger,x_mm,y_mm,pressure,phase\n";
  const int steps = std::max(2, static_cast<int>(seconds / 0.01));
  for (int i = 0; i <= steps; ++i) {
    const double f = static_cast<double>(i) / steps;
    out << f * seconds << ",0," << 5.0 + f * kGestureLengthMm << ",62,1,"
        << (i == 0 ? "down" : (i == steps ? "up" : "move")) << "\n";
  }
}

}  // namespace vimg::study_test
