// File replies' memory (docs/web-serving.md, "Connections"): one copy per file, shared by every reply of
// it, a budget on what the copies hold at once (shrunk here to 32 MiB so that two 24 MiB sparse
// files pass it; the default is kReplyBudgetBytes), and the wait for room of a request that finds
// it full (its bound set per test; the default is kReplyBudgetWait). Readers that never read keep
// their replies' writes pending (the files are larger than the sockets' buffers take). Each test
// says how it was seen to fail against a server broken on purpose.
#include <gtest/gtest.h>
#include <sys/socket.h>

#include <chrono>
#include <fstream>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "tests/net/raw_http.hpp"
#include "tests/web_server/site_fixture.hpp"
#include "tests/web_server/stub_api.hpp"

namespace vimg::test {
namespace {

constexpr std::size_t kFileBytes = std::size_t{24} << 20;
constexpr std::size_t kBudgetBytes = std::size_t{32} << 20;
constexpr int kSlowReaders = 20;

void sparse_file(const fs::path& path, std::size_t bytes) {
  { std::ofstream(path, std::ios::binary); }
  fs::resize_file(path, bytes);
}

// A slow reader of a.bin holding its 24 of the 32 MiB (its head read, then nothing), and `count`
// readers of b.bin sent after it, each of which finds the budget full.
struct Crowd {
  std::unique_ptr<RawConnection> slow;
  std::vector<std::unique_ptr<RawConnection>> waiting;
};

Crowd crowd_behind_a_slow_reader(int port, int count) {
  Crowd crowd;
  crowd.slow = std::make_unique<RawConnection>(port);
  EXPECT_TRUE(crowd.slow->send_all("GET /a.bin HTTP/1.1\r\nHost: localhost\r\n\r\n"));
  EXPECT_TRUE(crowd.slow->read_until("\r\n\r\n"));
  for (int i = 0; i < count; ++i) {
    crowd.waiting.push_back(std::make_unique<RawConnection>(port));
    EXPECT_TRUE(crowd.waiting.back()->send_all("GET /b.bin HTTP/1.1\r\nHost: localhost\r\nConnection: close\r\n\r\n"));
  }
  return crowd;
}

// Every waiting reader gets b.bin whole.
void expect_each_served_whole(const std::vector<std::unique_ptr<RawConnection>>& waiting) {
  for (const auto& connection : waiting) {
    ASSERT_TRUE(connection->read_to_end());
    const HttpResponse reply = parse_response(connection->received());
    EXPECT_EQ(reply.status, 200);
    EXPECT_EQ(reply.body.size(), kFileBytes);
  }
}

constexpr int kWaiting = web::kRouteWorkerThreads * 2;

class ReplyBudget : public SiteFixture {
 protected:
  // a.bin and b.bin of 24 MiB, a server whose budget is 32 MiB and whose wait for room outlasts
  // the test, and kWaiting readers of b.bin sent behind a slow reader of a.bin.
  WebServer& start_crowded(Crowd& crowd) {
    sparse_file(site_ / "a.bin", kFileBytes);
    sparse_file(site_ / "b.bin", kFileBytes);
    WebServer& server = start_server([](WebServerOptions& options) {
      options.limits.reply_budget_bytes = kBudgetBytes;
      options.limits.reply_budget_wait = kHangBound;
    });
    crowd = crowd_behind_a_slow_reader(port(), kWaiting);
    return server;
  }
};

// 20 readers of one 24 MiB file that never read hold one copy (24 MiB, not 480); another file
// that would pass the budget gets 503 with Retry-After (no wait for room here); a whole reader of the first is served
// from the shared copy; once the slow readers have gone the copy is freed and the other file is
// served. Seen to fail: with FileCopies::acquire's index lookup removed (no sharing), the second
// slow reader got 503; with reserve() always true (no budget), the other file got 200.
TEST_F(ReplyBudget, OneCopyPerFileWithinTheBudget) {
  sparse_file(site_ / "a.bin", kFileBytes);
  sparse_file(site_ / "b.bin", kFileBytes);
  WebServer& server = start_server([](WebServerOptions& options) {
    options.limits.reply_budget_bytes = kBudgetBytes;
    options.limits.reply_budget_wait = std::chrono::milliseconds(0);
  });
  std::vector<std::unique_ptr<RawConnection>> slow;
  for (int i = 0; i < kSlowReaders; ++i) {
    slow.push_back(std::make_unique<RawConnection>(port()));
    ASSERT_TRUE(slow.back()->send_all("GET /a.bin HTTP/1.1\r\nHost: localhost\r\n\r\n"));
    ASSERT_TRUE(slow.back()->read_until("\r\n\r\n"));  // the head; then nothing is read
    ASSERT_EQ(parse_response(slow.back()->received()).status, 200) << "reader " << i;
  }
  EXPECT_EQ(server.reply_bytes_held(), kFileBytes);
  HttpResponse refused = exchange(port(), "GET", "/b.bin");
  EXPECT_EQ(refused.status, 503);
  EXPECT_EQ(refused.headers["retry-after"], "1");
  const HttpResponse whole = exchange(port(), "GET", "/a.bin");
  EXPECT_EQ(whole.status, 200);
  EXPECT_EQ(whole.body.size(), kFileBytes);
  slow.clear();  // they close, their writes fail, the copy goes
  ASSERT_TRUE(wait_for([&] { return server.reply_bytes_held() == 0; })) << server.reply_bytes_held();
  EXPECT_EQ(exchange(port(), "GET", "/b.bin").status, 200);
  EXPECT_EQ(server.reply_bytes_held(), 0u);
}

// Requests that find the budget full wait for room, holding no reply and no worker: a slow reader
// of a.bin holds 24 of the 32 MiB; 8 readers of b.bin (more than the reading workers) wait, with
// nothing more held, while the page is still answered; once the slow reader goes, its copy is
// freed and each of the 8 is served b.bin whole (from one copy). Their wait is longer than the
// test (kHangBound), so only the freed room ends it. Seen to fail (the first b.bin reader got 503
// at once, so the server never counted it waiting) with serve_file's wait_for_room left false, as
// before.
TEST_F(ReplyBudget, RequestsThatFindTheBudgetFullAreServedOnceRoomIsFreed) {
  Crowd crowd;
  WebServer& server = start_crowded(crowd);
  auto& [slow, waiting] = crowd;
  ASSERT_TRUE(wait_for([&] { return server.counts().waiting_for_room == kWaiting; })) << server.counts().waiting_for_room;
  EXPECT_EQ(server.reply_bytes_held(), kFileBytes) << "a request waiting for room holds none";
  EXPECT_EQ(exchange(port(), "GET", "/index.html").status, 200) << "the waits hold no worker";
  for (auto& connection : waiting) {
    char byte = 0;
    EXPECT_EQ(::recv(connection->fd(), &byte, 1, MSG_DONTWAIT), -1) << "answered while waiting for room";
  }
  slow.reset();  // it closes: its write fails, the copy of a.bin is freed
  expect_each_served_whole(waiting);
  EXPECT_EQ(server.counts().waiting_for_room, 0);
  EXPECT_EQ(server.counts().room_waits_expired, 0);
}

// A change of the copies retries the requests waiting for room in the order they came, one at a
// time, and stops at the first that still finds none: 8 readers of b.bin wait beside a slow reader
// of a.bin; a page's file is served (its copy made, then freed: two changes) and a HEAD after it
// (no copy, no change) ends once both changes have been seen. The waiting requests' routes ran again
// at most twice in all (the first waiter's, once per change), not 8 times per change. Seen to fail
// (16 more routes than the 2 requests) with EngineState::wake_room_waiters retrying every waiter,
// as before.
TEST_F(ReplyBudget, AChangeRetriesTheFirstWaiterOnlyWhenItFindsNoRoom) {
  Crowd crowd;
  WebServer& server = start_crowded(crowd);
  auto& [slow, waiting] = crowd;
  ASSERT_TRUE(wait_for([&] { return server.counts().waiting_for_room == kWaiting; }));
  const long routes_before = server.counts().routes_queued;
  EXPECT_EQ(exchange(port(), "GET", "/index.html").status, 200);
  // Its copy was freed, and the change posted to the network thread, before its connection
  // closed; the HEAD's request is read after that change has been handled.
  EXPECT_EQ(exchange(port(), "HEAD", "/index.html").status, 200);
  ASSERT_TRUE(wait_for([&] { return server.counts().waiting_for_room == kWaiting; }));
  const long retries = server.counts().routes_queued - routes_before - 2;
  EXPECT_LE(retries, 2) << "routes run again for " << kWaiting << " waiters after two changes";
  slow.reset();  // room: every waiter is served in turn
  expect_each_served_whole(waiting);
  EXPECT_EQ(server.counts().waiting_for_room, 0);
}

// A waiter that would fit is not held for good behind the first, which does not: slow readers hold
// 20 + 10 of the 32 MiB; a reader of b.bin (24 MiB) waits, then one of c.bin (8 MiB). The 10 MiB
// reader goes: c.bin would fit, but the change retries b.bin first, which still does not, and c.bin
// waits behind it. When b.bin's wait ends (503), c.bin runs again and is served. Seen to fail (c.bin
// 503 at its own deadline) without the retry of the next waiter in Session::wait_for_room's timer.
// The wait (1 s here) only has to outlast the second reader's first try.
TEST_F(ReplyBudget, TheNextWaiterRunsAgainWhenTheFirstWaitEnds) {
  sparse_file(site_ / "a.bin", std::size_t{20} << 20);
  sparse_file(site_ / "d.bin", std::size_t{10} << 20);
  sparse_file(site_ / "b.bin", std::size_t{24} << 20);
  sparse_file(site_ / "c.bin", std::size_t{8} << 20);
  WebServer& server = start_server([](WebServerOptions& options) {
    options.limits.reply_budget_bytes = kBudgetBytes;
    options.limits.reply_budget_wait = std::chrono::milliseconds(1000);
  });
  RawConnection slow_a(port());
  auto slow_d = std::make_unique<RawConnection>(port());
  for (auto [connection, file] : {std::pair{&slow_a, "a"}, std::pair{slow_d.get(), "d"}}) {
    ASSERT_TRUE(connection->send_all(std::string("GET /") + file + ".bin HTTP/1.1\r\nHost: localhost\r\n\r\n"));
    ASSERT_TRUE(connection->read_until("\r\n\r\n"));
  }
  RawConnection first(port()), next(port());
  ASSERT_TRUE(first.send_all("GET /b.bin HTTP/1.1\r\nHost: localhost\r\nConnection: close\r\n\r\n"));
  ASSERT_TRUE(wait_for([&] { return server.counts().waiting_for_room == 1; }));
  ASSERT_TRUE(next.send_all("GET /c.bin HTTP/1.1\r\nHost: localhost\r\nConnection: close\r\n\r\n"));
  ASSERT_TRUE(wait_for([&] { return server.counts().waiting_for_room == 2; }));
  slow_d.reset();
  ASSERT_TRUE(first.read_to_end());
  EXPECT_EQ(parse_response(first.received()).status, 503);
  ASSERT_TRUE(next.read_to_end());
  const HttpResponse reply = parse_response(next.received());
  EXPECT_EQ(reply.status, 200);
  EXPECT_EQ(reply.body.size(), std::size_t{8} << 20);
  EXPECT_EQ(server.counts().room_waits_expired, 1);
}

// The waiter run again for room is never held behind another route of its client (one key's routes
// otherwise run one at a time): a reader of b.bin with key k1 waits for room, then k1's other
// request is held in its route, and an unkeyed reader of b.bin waits behind the first. Once the
// slow reader goes, both are served while k1's other request is still held. Seen to fail (no reply
// within the client's 60 s: the first waiter's retry queued behind k1's held route, and the
// second never tried) with Session::queue_route keeping the client's turn for a route run again.
TEST_F(ReplyBudget, AWaiterRunAgainSkipsItsClientsTurn) {
  StubApi api(root_ / "answers.txt");
  sparse_file(site_ / "a.bin", kFileBytes);
  sparse_file(site_ / "b.bin", kFileBytes);
  WebServer& server = start_server([&](WebServerOptions& options) {
    api.install(options);
    options.limits.reply_budget_bytes = kBudgetBytes;
    options.limits.reply_budget_wait = kHangBound;
  });
  auto slow = std::make_unique<RawConnection>(port());
  ASSERT_TRUE(slow->send_all("GET /a.bin HTTP/1.1\r\nHost: localhost\r\n\r\n"));
  ASSERT_TRUE(slow->read_until("\r\n\r\n"));
  RawConnection keyed(port()), held(port()), unkeyed(port());
  ASSERT_TRUE(keyed.send_all("GET /b.bin HTTP/1.1\r\nHost: localhost\r\nX-Vimg-Key: k1\r\nConnection: close\r\n\r\n"));
  ASSERT_TRUE(wait_for([&] { return server.counts().waiting_for_room == 1; }));
  ASSERT_TRUE(held.send_all("GET /api/block HTTP/1.1\r\nHost: localhost\r\nX-Vimg-Key: k1\r\nConnection: close\r\n\r\n"));
  ASSERT_TRUE(api.reads.wait_for_waiters(1));  // k1's turn is taken
  ASSERT_TRUE(unkeyed.send_all("GET /b.bin HTTP/1.1\r\nHost: localhost\r\nConnection: close\r\n\r\n"));
  ASSERT_TRUE(wait_for([&] { return server.counts().waiting_for_room == 2; }));
  slow.reset();
  for (RawConnection* waiter : {&keyed, &unkeyed}) {
    ASSERT_TRUE(waiter->read_to_end());
    const HttpResponse reply = parse_response(waiter->received());
    EXPECT_EQ(reply.status, 200);
    EXPECT_EQ(reply.body.size(), kFileBytes);
  }
  api.reads.open();
  ASSERT_TRUE(held.read_to_end());
  EXPECT_EQ(parse_response(held.received()).status, 200);
}

// A request waits for room no longer than the reply budget wait (shrunk here to 300 ms): then it
// gets 503 with Retry-After, while the slow reader still holds its copy and nothing else is held.
// Seen to fail (no reply within the client's 60 s: the wait never ended) with the wait's timer
// not armed in Session::wait_for_room.
TEST_F(ReplyBudget, ARequestWaitsForRoomNoLongerThanTheBudgetWait) {
  constexpr std::chrono::milliseconds kWait{300};
  sparse_file(site_ / "a.bin", kFileBytes);
  sparse_file(site_ / "b.bin", kFileBytes);
  WebServer& server = start_server([&](WebServerOptions& options) {
    options.limits.reply_budget_bytes = kBudgetBytes;
    options.limits.reply_budget_wait = kWait;
  });
  RawConnection slow(port());
  ASSERT_TRUE(slow.send_all("GET /a.bin HTTP/1.1\r\nHost: localhost\r\n\r\n"));
  ASSERT_TRUE(slow.read_until("\r\n\r\n"));
  const auto sent = std::chrono::steady_clock::now();
  HttpResponse refused = exchange(port(), "GET", "/b.bin");
  const auto waited = std::chrono::steady_clock::now() - sent;
  EXPECT_EQ(refused.status, 503);
  EXPECT_EQ(refused.headers["retry-after"], "1");
  EXPECT_GE(waited, kWait) << "answered before its wait ended";
  EXPECT_EQ(server.counts().room_waits_expired, 1);
  EXPECT_EQ(server.counts().waiting_for_room, 0);
  EXPECT_EQ(server.reply_bytes_held(), kFileBytes);
}

// stop() (SIGINT, SIGTERM) answers a request waiting for room at once: its 503, then the close,
// well before the stop's grace deadline. Seen to fail (no reply: the connection was closed at the
// grace deadline, shrunk here to 2 s) with Session::stop_gracefully leaving a waiting request be,
// as a route under way.
TEST_F(ReplyBudget, StopAnswersARequestWaitingForRoom) {
  sparse_file(site_ / "a.bin", kFileBytes);
  sparse_file(site_ / "b.bin", kFileBytes);
  WebServer& server = start_server([](WebServerOptions& options) {
    options.limits.reply_budget_bytes = kBudgetBytes;
    options.limits.reply_budget_wait = kHangBound;
    options.limits.stop_grace_deadline = std::chrono::milliseconds(2000);
  });
  RawConnection slow(port());
  ASSERT_TRUE(slow.send_all("GET /a.bin HTTP/1.1\r\nHost: localhost\r\n\r\n"));
  ASSERT_TRUE(slow.read_until("\r\n\r\n"));
  RawConnection waiting(port());
  ASSERT_TRUE(waiting.send_all("GET /b.bin HTTP/1.1\r\nHost: localhost\r\n\r\n"));
  ASSERT_TRUE(wait_for([&] { return server.counts().waiting_for_room == 1; }));
  server.stop();
  ASSERT_TRUE(waiting.read_to_end()) << waiting.received();
  HttpResponse reply = parse_response(waiting.received());
  EXPECT_EQ(reply.status, 503);
  EXPECT_EQ(reply.headers["connection"], "close");
}

// A file larger than the whole budget could never find room: 503 at once, without a wait (the
// wait here is an hour). Seen to fail (no reply within the client's 60 s) with serve_file setting
// wait_for_room whatever the file's size.
TEST_F(ReplyBudget, AFileLargerThanTheWholeBudgetIs503AtOnce) {
  sparse_file(site_ / "a.bin", kFileBytes);
  WebServer& server = start_server([](WebServerOptions& options) {
    options.limits.reply_budget_bytes = kFileBytes - 1;
    options.limits.reply_budget_wait = std::chrono::hours(1);
  });
  HttpResponse refused = exchange(port(), "GET", "/a.bin");
  EXPECT_EQ(refused.status, 503);
  EXPECT_EQ(refused.headers["retry-after"], "1");
  EXPECT_EQ(server.counts().room_waits_expired, 0) << "it waited";
  EXPECT_EQ(server.reply_bytes_held(), 0u);
}

// HEAD of a file reads none of it: no copy, nothing held. Seen to fail (the budget held the file
// during the reply, and a HEAD of b.bin beside a slow reader of a.bin got 503) with serve_file
// making a copy for HEAD too.
TEST_F(ReplyBudget, HeadHoldsNoCopy) {
  sparse_file(site_ / "a.bin", kFileBytes);
  sparse_file(site_ / "b.bin", kFileBytes);
  WebServer& server = start_server([](WebServerOptions& options) { options.limits.reply_budget_bytes = kBudgetBytes; });
  RawConnection slow(port());
  ASSERT_TRUE(slow.send_all("GET /a.bin HTTP/1.1\r\nHost: localhost\r\n\r\n"));
  ASSERT_TRUE(slow.read_until("\r\n\r\n"));
  HttpResponse head = exchange(port(), "HEAD", "/b.bin");
  EXPECT_EQ(head.status, 200);
  EXPECT_EQ(head.headers["content-length"], std::to_string(kFileBytes));
  EXPECT_EQ(head.body, "");
  EXPECT_EQ(server.reply_bytes_held(), kFileBytes);
}

}  // namespace
}  // namespace vimg::test
