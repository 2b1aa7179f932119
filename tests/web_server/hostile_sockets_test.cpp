// Idle and slow connections cost the server no worker (docs/web-serving.md, "Serving"): while a few dozen
// sockets say nothing and a few dozen more send their headers a byte at a time (each reconnecting at
// once when the server closes it, as a hostile client does), a participant's answers through the API
// and a page's file are each confirmed within kPromptBound of being sent. A server that gives each
// connection a worker of a fixed pool (24) has every worker held by the slow sockets and answers
// nobody. The hostile sockets' pace is theirs; the test waits only on states (all hostile sockets
// connected, each reply's bytes), and kPromptBound is generous: the server answers in milliseconds.
// Also: a closed event stream gives its place back at once.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "tests/net/hostile_clients.hpp"
#include "tests/net/raw_http.hpp"
#include "tests/web_server/site_fixture.hpp"
#include "web/server/event_stream.hpp"

namespace vimg::test {
namespace {

using HostileSockets = SiteFixture;
using Clock = std::chrono::steady_clock;

constexpr int kSilentSockets = 40;
constexpr int kSlowSockets = 30;  // more than the 24 workers a thread-per-connection server had
constexpr int kAnswers = 20;
constexpr std::chrono::seconds kPromptBound{5};
constexpr std::chrono::milliseconds kSlowBytePeriod{200};

// One request; the status, or 0 when no reply came within kPromptBound.
int answered_promptly(int port, const std::string& request) {
  RawConnection connection(port);
  if (!connection.connected() || !connection.send_all(request)) return 0;
  if (!connection.read_to_end(kPromptBound)) return 0;
  return parse_response(connection.received()).status;
}

TEST_F(HostileSockets, AParticipantIsAnsweredBesideSilentAndSlowSockets) {
  std::mutex answers_mutex;
  std::vector<std::string> answers;
  WebServerOptions options;
  options.site_dir = site_;
  options.log_line = [](const std::string&) {};
  options.api = [&](const web::ApiRequest& request) {
    const std::lock_guard lock(answers_mutex);
    answers.push_back(request.body);
    return web::body_reply(200, "application/json", "{\"completed\": " + std::to_string(answers.size()) + "}");
  };
  options.api_post_paths = {"/api/answer"};
  server_ = std::make_unique<WebServer>(options);
  ASSERT_FALSE(server_->start());
  HostileClients hostile(port(), kSilentSockets, kSlowSockets, kSlowBytePeriod);
  while (!hostile.all_connected()) std::this_thread::yield();  // a state: every hostile socket is in
  for (int trial = 1; trial <= kAnswers; ++trial) {
    const std::string body = "trial=" + std::to_string(trial);
    const auto sent = Clock::now();
    const int status = answered_promptly(port(), "POST /api/answer HTTP/1.1\r\nHost: localhost\r\nConnection: close\r\n"
                                                 "Content-Length: " + std::to_string(body.size()) + "\r\n\r\n" + body);
    ASSERT_EQ(status, 200) << "answer " << trial << " not confirmed within " << kPromptBound.count() << " s (after "
                           << std::chrono::duration_cast<std::chrono::milliseconds>(Clock::now() - sent).count() << " ms)";
    ASSERT_EQ(answered_promptly(port(), "GET /index.html HTTP/1.1\r\nHost: localhost\r\nConnection: close\r\n\r\n"), 200)
        << "after answer " << trial;
  }
  {
    const std::lock_guard lock(answers_mutex);
    ASSERT_EQ(answers.size(), std::size_t{kAnswers});
    for (int trial = 1; trial <= kAnswers; ++trial) EXPECT_EQ(answers[trial - 1], "trial=" + std::to_string(trial));
  }
  // Every hostile socket, silent or slow, is closed by the server at its header deadline (and
  // comes back). Seen to fail (none reopened within the bound) with the header deadline removed
  // from Session::read_header.
  const auto give_up = Clock::now() + 3 * web::kHeaderDeadline;
  while (hostile.reopened() < kSilentSockets + kSlowSockets && Clock::now() < give_up) std::this_thread::yield();
  EXPECT_GE(hostile.reopened(), kSilentSockets + kSlowSockets);
}

// A page that closes its event stream frees its place among the kMaxEventStreams at once, not at
// the server's next keep-alive comment (15 s): pages that come and go (reloads, a poller that
// only checks the greeting) never lock the others out.
TEST_F(HostileSockets, AClosedEventStreamFreesItsPlaceAtOnce) {
  start_server();
  for (int round = 0; round < 3; ++round) {
    {
      std::vector<std::unique_ptr<RawConnection>> pages;
      for (int i = 0; i < web::kMaxEventStreams; ++i) {
        pages.push_back(std::make_unique<RawConnection>(port()));
        ASSERT_TRUE(pages.back()->send_all("GET /events HTTP/1.1\r\nHost: localhost\r\n\r\n"));
        ASSERT_TRUE(pages.back()->read_until(": connected\n")) << pages.back()->received();
      }
      EXPECT_EQ(server_->open_event_streams(), web::kMaxEventStreams);
    }  // every page closes its stream
    const auto give_up = Clock::now() + kPromptBound;
    while (server_->open_event_streams() > 0 && Clock::now() < give_up) std::this_thread::yield();
    ASSERT_EQ(server_->open_event_streams(), 0) << "round " << round << ": closed streams still hold their places";
  }
}

}  // namespace
}  // namespace vimg::test
