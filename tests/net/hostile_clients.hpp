#pragma once
// Hostile clients of a server on 127.0.0.1:PORT, on a thread of their own (the HostileSockets test
// and bench/study_load): silent sockets connect and never send; slow ones send a request line, then
// one header byte every `slow_period`. A socket the server closed is opened again at once. Their
// pace is theirs; nothing here waits for the server.
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <thread>
#include <vector>

#include "tests/net/raw_http.hpp"

namespace vimg::test {

class HostileClients {
 public:
  HostileClients(int port, int silent, int slow, std::chrono::milliseconds slow_period)
      : port_(port), silent_(silent), slow_(slow), slow_period_(slow_period), thread_([this] { run(); }) {}
  ~HostileClients() {
    stop_ = true;
    thread_.join();
  }
  HostileClients(const HostileClients&) = delete;
  HostileClients& operator=(const HostileClients&) = delete;

  // Whether every hostile socket has been connected at least once.
  bool all_connected() const { return connected_ >= silent_ + slow_; }
  int reopened() const { return reopened_; }  // sockets opened again after the server closed them
  int open_now() const { return open_now_; }  // sockets open after the last pass

 private:
  using Clock = std::chrono::steady_clock;
  static constexpr std::chrono::milliseconds kLongestPoll{100};  // how soon stop() is seen

  bool slow(std::size_t i) const { return static_cast<int>(i) >= silent_; }
  void open(int& fd, bool slow_socket) {
    fd = connect_loopback(port_, true);
    if (fd >= 0 && slow_socket) ::send(fd, "GET / HTTP/1.1\r\nX-Slow: ", 24, MSG_NOSIGNAL);
  }
  void run() {
    std::vector<int> fds(static_cast<std::size_t>(silent_ + slow_), -1);
    for (std::size_t i = 0; i < fds.size(); ++i) {
      open(fds[i], slow(i));
      if (fds[i] >= 0) ++connected_;
    }
    auto next_byte = Clock::now() + slow_period_;
    while (!stop_) {
      std::vector<pollfd> polled;
      for (const int fd : fds) polled.push_back({fd, POLLIN, 0});
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(next_byte - Clock::now());
      ::poll(polled.data(), polled.size(), static_cast<int>(std::clamp(left, std::chrono::milliseconds(0), kLongestPoll).count()));
      int open_count = 0;
      for (std::size_t i = 0; i < fds.size(); ++i) {
        char scratch[1024];
        if (fds[i] < 0 || (polled[i].revents != 0 && ::recv(fds[i], scratch, sizeof scratch, 0) <= 0)) {
          if (fds[i] >= 0) ::close(fds[i]);
          open(fds[i], slow(i));  // the server closed it (or it could not connect): come back at once
          ++reopened_;
          if (connected_ < silent_ + slow_ && fds[i] >= 0) ++connected_;
        }
        if (fds[i] >= 0) ++open_count;
      }
      open_now_ = open_count;
      if (Clock::now() >= next_byte) {
        for (std::size_t i = static_cast<std::size_t>(silent_); i < fds.size(); ++i) {
          if (fds[i] >= 0) ::send(fds[i], "a", 1, MSG_NOSIGNAL);
        }
        next_byte += slow_period_;
      }
    }
    for (const int fd : fds) {
      if (fd >= 0) ::close(fd);
    }
  }

  int port_, silent_, slow_;
  std::chrono::milliseconds slow_period_;
  std::atomic<bool> stop_{false};
  std::atomic<int> connected_{0}, reopened_{0}, open_now_{0};
  std::thread thread_;  // last: it starts once the members above are set
};

}  // namespace vimg::test
