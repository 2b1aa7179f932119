// The study API's rate limit (docs/web-serving.md, "Connections") checked as a request arrives, before it
// waits for anything: the real StudyService in a WebServer (StudyService::install), over raw
// sockets, with a slow file layer: this program's fsync (which replaces the C library's for every
// caller linked in, TrialLog among them) waits at a Gate (tests/web_server/stub_api.hpp) while the
// test holds it, as a disk whose fsync does not return.
#include <gtest/gtest.h>
#include <poll.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "storage/study/study_file.hpp"
#include "study/matching_row.hpp"
#include "study/trial_plan.hpp"
#include "tests/net/raw_http.hpp"
#include "tests/study_server/study_fixture.hpp"
#include "tests/web_server/stub_api.hpp"
#include "web/study_server/participant_logs.hpp"
#include "web/study_server/study_service.hpp"

namespace {

// While set, every fsync of this program waits at it first.
std::atomic<vimg::test::Gate*> g_fsync_gate{nullptr};

}  // namespace

extern "C" int fsync(int fd) {
  if (vimg::test::Gate* gate = g_fsync_gate.load()) gate->wait();
  return static_cast<int>(::syscall(SYS_fsync, fd));
}

namespace vimg::test {
namespace {

namespace fs = std::filesystem;

// Whether the server has sent something on `fd` (its reply), without waiting.
bool replied(int fd) {
  pollfd p{fd, POLLIN, 0};
  return ::poll(&p, 1, 0) == 1;
}

// One participant's first answer is being synced (its fsync held: it holds the participant's turn
// on the writing workers and the participant's lock); the same participant then sends 40 answers
// at once, more than its bucket holds (20 at once, the first spent). Those beyond the bucket are
// answered 429 while the first answer is still held, that is at once, without waiting behind it;
// once the disk goes on, the first is recorded (200) and the ones the bucket let through are
// answered in turn (409: trial 1 is done). Seen to fail (no reply came while the fsync was held;
// the wait ended after kHangBound) with the screen run on the worker just before the route, as
// before (the rate limit checked only once the request's turn had come).
TEST(StudyRateLimit, AFloodBehindASlowAnswerIsRefusedAtOnce) {
  constexpr int kFlood = 40;
  // The bucket lets 19 more through at once; it refills at 4 a second, so the test allows 1.5 s of
  // refill before it would count fewer refusals than this.
  constexpr int kRefusedAtLeast = kFlood - static_cast<int>(web::kAnswerBurst - 1) - 6;
  const fs::path dir = fs::path(VIMG_BINARY_DIR) / "study_server_tests" / "StudyRateLimit";
  fs::remove_all(dir);
  fs::create_directories(dir / "site");
  fs::create_directories(dir / "results");
  std::ofstream(dir / "site" / "index.html") << "<!doctype html><title>study</title>";
  auto loaded = load_matching_study(kExampleStudy);
  ASSERT_TRUE(loaded.ok());
  const MatchingStudy study = *loaded.study;
  const auto stems = study::matching_study_stems(study);
  StudySecret secret{};
  secret[0] = 7;
  web::StudyService service(study, stems, dir / "results", web::StudyKeys(secret), [](const std::string&) {});
  Gate disk;  // declared before the server, which stops before it goes
  web::WebServerOptions options;
  options.site_dir = dir / "site";
  options.log_line = [](const std::string&) {};
  service.install(options);
  web::WebServer server(options);
  // Whatever ends the test, the disk goes on before the server stops (it waits for the answer).
  struct Release {
    Gate& disk;
    ~Release() {
      g_fsync_gate = nullptr;
      disk.open();
    }
  } release{disk};
  ASSERT_FALSE(server.start());

  const auto plan = study::plan_matching_trials(study, "p1");
  const std::string stem = stems[plan[0].set][plan[0].image];
  const std::string body = "participant=p1&trial=1&presented=" + stem + "&chosen=" + stem +
                           "&rub_s=1.5&response_s=0.25&path_mm=12.5";
  const std::string answer = "POST /api/answer HTTP/1.1\r\nHost: localhost\r\nOrigin: http://localhost\r\nX-Vimg-Key: " +
                             web::StudyKeys(secret).participant_key("p1") +
                             "\r\nConnection: close\r\nContent-Type: application/x-www-form-urlencoded\r\nContent-Length: " +
                             std::to_string(body.size()) + "\r\n\r\n" + body;

  g_fsync_gate = &disk;
  RawConnection first(server.port());
  ASSERT_TRUE(first.send_all(answer));
  ASSERT_TRUE(disk.wait_for_waiters(1));  // a state: the first answer's fsync is held
  std::vector<std::unique_ptr<RawConnection>> flood;
  for (int i = 0; i < kFlood; ++i) {
    flood.push_back(std::make_unique<RawConnection>(server.port()));
    ASSERT_TRUE(flood.back()->send_all(answer));
  }
  const auto sent = std::chrono::steady_clock::now();
  // A state: kRefusedAtLeast of the flood have their reply while the first answer's fsync is held.
  std::vector<bool> answered(kFlood, false);
  int refused = 0;
  ASSERT_TRUE(wait_for([&] {
    for (int i = 0; i < kFlood; ++i) {
      if (answered[i] || !replied(flood[i]->fd())) continue;
      answered[i] = true;
      flood[i]->read_to_end();
      EXPECT_EQ(parse_response(flood[i]->received()).status, 429) << flood[i]->received();
      ++refused;
    }
    return refused >= kRefusedAtLeast;
  })) << refused << " refused while the first answer was held";
  RecordProperty("refused_while_the_first_answer_was_held", refused);
  RecordProperty("ms_to_refuse_the_flood", static_cast<int>(std::chrono::duration_cast<std::chrono::milliseconds>(
                                               std::chrono::steady_clock::now() - sent).count()));
  EXPECT_FALSE(replied(first.fd())) << "the first answer was answered before its fsync";

  g_fsync_gate = nullptr;
  disk.open();
  ASSERT_TRUE(first.read_to_end());
  EXPECT_EQ(parse_response(first.received()).status, 200) << first.received();
  int too_many = 0, not_next = 0;
  for (auto& connection : flood) {
    ASSERT_TRUE(connection->read_to_end());
    const int status = parse_response(connection->received()).status;
    too_many += status == 429;
    not_next += status == 409;
  }
  EXPECT_EQ(too_many + not_next, kFlood);
  EXPECT_GE(too_many, kRefusedAtLeast);
  server.stop();
  std::ifstream rows(dir / "results" / "p1.trials.csv");
  int lines = 0;
  for (std::string line; std::getline(rows, line);) ++lines;
  EXPECT_EQ(lines, 2) << "the header and the first answer's row";
}

}  // namespace
}  // namespace vimg::test
