#pragma once
// `vimg serve --study` on the shipped matching example as a process (tests/web_server's
// ServeProcess: --port 0, the URL read from its stdout), a results folder of the test's own, and
// the participant's plan computed here with the trial-plan code, so that a test knows which image
// each trial presents. Requests go over raw sockets (tests/net/raw_http.hpp), which send
// "Host: localhost": this server's own page thus has Origin http://localhost.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <string>
#include <vector>

#include "storage/study/study_file.hpp"
#include "study/matching_row.hpp"
#include "study/trial_plan.hpp"
#include "tests/cli/run_command.hpp"
#include "tests/net/raw_http.hpp"
#include "tests/web_server/serve_process.hpp"

namespace vimg::test {

inline const std::filesystem::path kExampleStudy =
    std::filesystem::path(VIMG_SOURCE_DIR) / "assets/examples/matching/study.xml";
inline constexpr const char* kOwnOrigin = "http://localhost";

inline std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// A well-formed answer (with "&path_mm=12.5") made `bytes` long by writing path_mm with trailing zeros.
inline std::string answer_of_size(const std::string& answer, std::size_t bytes) {
  const std::string path_field = "&path_mm=12.5";
  const std::size_t at = answer.find(path_field) + path_field.size();
  return answer.substr(0, at) + std::string(bytes - answer.size(), '0') + answer.substr(at);
}

class StudyServer : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::path(VIMG_BINARY_DIR) / "study_server_tests" /
           (std::string("StudyServer.") + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_ / "tmp");
    std::filesystem::create_directories(results());
    write_stand_in_assets(dir_ / "assets");
    auto loaded = load_matching_study(kExampleStudy);
    ASSERT_TRUE(loaded.ok());
    study_ = *loaded.study;
    stems_ = study::matching_study_stems(study_);
  }

  std::filesystem::path results() const { return dir_ / "results"; }
  std::filesystem::path trial_file(const std::string& participant) const {
    return results() / (participant + ".trials.csv");
  }

  // Starts the server; its port (the test fails without one).
  int start() {
    serve_ = std::make_unique<ServeProcess>(
        std::vector<std::string>{"--study", kExampleStudy.string(), "--results", results().string()}, dir_ / "assets",
        dir_ / "tmp");
    port_ = serve_->wait_for_port();
    EXPECT_GT(port_, 0) << serve_->printed();
    return port_;
  }
  // The researcher's key, from the dashboard URL the server printed.
  std::string researcher_key() const {
    const std::string& out = serve_->printed();
    const std::size_t at = out.find("#key=");
    return at == std::string::npos ? std::string() : out.substr(at + 5, 32);
  }
  // The participant's key, from the link `vimg study link` prints.
  std::string participant_key(const std::string& participant) const {
    const CommandRun run = run_command(kVimg + " study link '" + results().string() + "' --participant " + participant +
                                       " --url http://127.0.0.1/");
    EXPECT_EQ(run.exit_code, 0) << run.out;
    const std::size_t at = run.out.find("&key=");
    return at == std::string::npos ? std::string() : run.out.substr(at + 5, 32);
  }

  std::string presented(const std::string& participant, std::size_t trial) const {
    const auto plan = study::plan_matching_trials(study_, participant);
    return stems_[plan[trial - 1].set][plan[trial - 1].image];
  }
  std::string first_of_set(const std::string& participant, std::size_t trial) const {
    const auto plan = study::plan_matching_trials(study_, participant);
    return stems_[plan[trial - 1].set][0];
  }
  std::string answer_body(const std::string& participant, std::size_t trial, const std::string& presented,
                          const std::string& chosen, const std::string& extra = "") const {
    return "participant=" + participant + "&trial=" + std::to_string(trial) + "&presented=" + presented +
           "&chosen=" + chosen + "&rub_s=1.5&response_s=0.25&path_mm=12.5" + extra;
  }
  // The answer for `trial` the plan expects, choosing the set's first image.
  std::string good_answer(const std::string& participant, std::size_t trial) const {
    return answer_body(participant, trial, presented(participant, trial), first_of_set(participant, trial));
  }

  HttpResponse post(const std::string& path, const std::string& key, const std::string& body,
                    const std::string& origin = kOwnOrigin) const {
    std::string headers = "Content-Type: application/x-www-form-urlencoded\r\nContent-Length: " +
                          std::to_string(body.size()) + "\r\n";
    if (!key.empty()) headers += "X-Vimg-Key: " + key + "\r\n";
    if (!origin.empty()) headers += "Origin: " + origin + "\r\n";
    return exchange(port_, "POST", path, headers, body);
  }
  HttpResponse get(const std::string& target, const std::string& key) const {
    return exchange(port_, "GET", target, key.empty() ? "" : "X-Vimg-Key: " + key + "\r\n");
  }

  std::filesystem::path dir_;
  MatchingStudy study_;
  std::vector<std::vector<std::string>> stems_;
  std::unique_ptr<ServeProcess> serve_;
  int port_ = 0;
};

}  // namespace vimg::test
