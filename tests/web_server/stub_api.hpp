#pragma once
// An API for the server's own tests (WebServerOptions::api), standing in for the study's, whose
// routes the tests can hold, count and break:
//   GET  /api/state   200 at once (a participant's state: only reads)
//   GET  /api/count   200 with the number of times this route has run
//   GET  /api/block   waits until `reads` opens (holds a reading worker)
//   GET  /api/throw   throws std::runtime_error("injected fault")
//   GET  /api/early   refused 429 by the screen (WebServerOptions::api_screen), on the network thread
//   GET  /api/early-throw  the screen throws std::runtime_error("injected screen fault")
//   POST /api/answer  writes the body to answers.txt and syncs it through the slow file layer:
//                     the sync waits until `disk` opens (a disk whose fsync never returns)
// Waits are on states (Gate::wait_for_waiters), with kHangBound only to end a hang.
#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <filesystem>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>

#include "tests/net/raw_http.hpp"
#include "web/server/web_server.hpp"

namespace vimg::test {

// Threads wait at it until it opens; the test can wait until n of them are there.
class Gate {
 public:
  void wait() {
    std::unique_lock lock(mutex_);
    ++waiting_;
    changed_.notify_all();
    changed_.wait(lock, [&] { return open_; });
    --waiting_;
  }
  void open() {
    const std::lock_guard lock(mutex_);
    open_ = true;
    changed_.notify_all();
  }
  bool wait_for_waiters(int n) {
    std::unique_lock lock(mutex_);
    return changed_.wait_for(lock, kHangBound, [&] { return waiting_ >= n; });
  }
  ~Gate() { open(); }

 private:
  std::mutex mutex_;
  std::condition_variable changed_;
  int waiting_ = 0;
  bool open_ = false;
};

class StubApi {
 public:
  explicit StubApi(std::filesystem::path answers_file) : answers_file_(std::move(answers_file)) {}

  Gate reads, disk;
  std::atomic<int> counted{0}, answers_synced{0};

  void install(web::WebServerOptions& options) {
    options.api = [this](const web::ApiRequest& request) { return handle(request); };
    options.api_post_paths = {"/api/answer"};
    options.api_screen = [](const web::ApiRequest& request) -> std::optional<web::ApiReply> {
      if (request.path == "/api/early") return web::body_reply(429, "text/plain", "refused early");
      if (request.path == "/api/early-throw") throw std::runtime_error("injected screen fault");
      return std::nullopt;
    };
  }

  web::ApiReply handle(const web::ApiRequest& request) {
    if (request.path == "/api/state") return web::body_reply(200, "application/json", "{\"state\": 1}");
    if (request.path == "/api/count") return web::body_reply(200, "text/plain", std::to_string(++counted));
    if (request.path == "/api/block") {
      reads.wait();
      return web::body_reply(200, "text/plain", "unblocked");
    }
    if (request.path == "/api/throw") throw std::runtime_error("injected fault");
    if (request.path == "/api/answer") return answer(request.body);
    return web::body_reply(404, "text/plain", "not found");
  }

 private:
  // The slow file layer: the row is written, then its sync waits for the disk.
  web::ApiReply answer(const std::string& body) {
    const int fd = ::open(answers_file_.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
    if (fd < 0) return web::body_reply(500, "text/plain", "cannot open");
    const std::string row = body + "\n";
    const bool written = ::write(fd, row.data(), row.size()) == static_cast<ssize_t>(row.size());
    disk.wait();
    const bool synced = written && ::fsync(fd) == 0;
    ::close(fd);
    if (!synced) return web::body_reply(500, "text/plain", "cannot write");
    ++answers_synced;
    return web::body_reply(200, "application/json", "{\"recorded\": 1}");
  }

  std::filesystem::path answers_file_;
};

inline std::string get_request(const std::string& target) {
  return "GET " + target + " HTTP/1.1\r\nHost: localhost\r\nConnection: close\r\n\r\n";
}

inline std::string post_request(const std::string& target, const std::string& body) {
  return "POST " + target + " HTTP/1.1\r\nHost: localhost\r\nConnection: close\r\nContent-Length: " +
         std::to_string(body.size()) + "\r\n\r\n" + body;
}

}  // namespace vimg::test
