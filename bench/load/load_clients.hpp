#pragma once
// The clients of the study server's load run (bench/study_load.cpp): one HTTP request over a socket
// of its own with a bound, the hostile sockets (silent, or a header byte at a time) held open on a
// thread of their own, and `vimg serve` as a child process whose printed URL gives the port.
#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <poll.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdlib>
#include <string>
#include <thread>
#include <vector>

namespace vimg::bench {

using Clock = std::chrono::steady_clock;

inline double ms_since(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

inline int connect_to(int port, bool non_blocking = false) {
  const int fd = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
  if (fd < 0) return -1;
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_port = htons(static_cast<std::uint16_t>(port));
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  if (::connect(fd, reinterpret_cast<const sockaddr*>(&address), sizeof address) != 0) {
    ::close(fd);
    return -1;
  }
  if (non_blocking) ::fcntl(fd, F_SETFL, O_NONBLOCK);
  return fd;
}

struct Reply {
  int status = 0;  // 0: no reply within the bound (refused, reset, or too slow)
  std::string body;
};

// One request with Connection: close; the reply, read until the server closes, within `bound`.
inline Reply request(int port, const std::string& text, std::chrono::milliseconds bound) {
  const auto give_up = Clock::now() + bound;
  const int fd = connect_to(port);
  if (fd < 0) return {};
  std::string received;
  bool sent = ::send(fd, text.data(), text.size(), MSG_NOSIGNAL) == static_cast<ssize_t>(text.size());
  while (sent) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(give_up - Clock::now()).count();
    pollfd p{fd, POLLIN, 0};
    if (left <= 0 || ::poll(&p, 1, static_cast<int>(left)) <= 0) break;
    char buffer[4096];
    const ssize_t n = ::recv(fd, buffer, sizeof buffer, 0);
    if (n <= 0) break;
    received.append(buffer, static_cast<std::size_t>(n));
  }
  ::close(fd);
  Reply reply;
  const std::size_t head_end = received.find("\r\n\r\n");
  if (received.rfind("HTTP/1.", 0) != 0 || head_end == std::string::npos) return reply;
  reply.status = std::atoi(received.c_str() + 9);
  reply.body = received.substr(head_end + 4);
  return reply;
}

// One connection kept open for a participant's requests, as a browser keeps one: a request that
// finds it closed by the server (idle too long) is sent again once on a new connection.
class KeepAliveClient {
 public:
  explicit KeepAliveClient(int port) : port_(port) {}
  ~KeepAliveClient() { drop(); }
  KeepAliveClient(const KeepAliveClient&) = delete;
  KeepAliveClient& operator=(const KeepAliveClient&) = delete;

  Reply request(const std::string& text, std::chrono::milliseconds bound) {
    const auto give_up = Clock::now() + bound;
    for (int attempt = 0; attempt < 2; ++attempt) {
      const bool reused = fd_ >= 0;
      if (fd_ < 0) fd_ = connect_to(port_);
      if (fd_ < 0) return {};
      Reply reply;
      if (::send(fd_, text.data(), text.size(), MSG_NOSIGNAL) == static_cast<ssize_t>(text.size())) reply = read_reply(give_up);
      if (reply.status != 0) return reply;
      drop();
      if (!reused) break;
    }
    return {};
  }

 private:
  void drop() {
    if (fd_ >= 0) ::close(fd_);
    fd_ = -1;
  }
  // One response: its head, then Content-Length bytes of body.
  Reply read_reply(Clock::time_point give_up) {
    std::string received;
    std::size_t need = std::string::npos;
    while (received.size() < need) {
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(give_up - Clock::now()).count();
      pollfd p{fd_, POLLIN, 0};
      if (left <= 0 || ::poll(&p, 1, static_cast<int>(left)) <= 0) return {};
      char buffer[4096];
      const ssize_t n = ::recv(fd_, buffer, sizeof buffer, 0);
      if (n <= 0) return {};
      received.append(buffer, static_cast<std::size_t>(n));
      const std::size_t head_end = received.find("\r\n\r\n");
      if (need == std::string::npos && head_end != std::string::npos) {
        const std::size_t length = received.find("Content-Length: ");
        need = head_end + 4 + (length < head_end ? std::strtoul(received.c_str() + length + 16, nullptr, 10) : 0);
      }
    }
    if (received.rfind("HTTP/1.", 0) != 0) return {};
    Reply reply;
    reply.status = std::atoi(received.c_str() + 9);
    reply.body = received.substr(received.find("\r\n\r\n") + 4);
    if (received.find("Connection: close") != std::string::npos) drop();
    return reply;
  }

  int port_;
  int fd_ = -1;
};

// Silent sockets connect and say nothing; slow ones send a request line, then one header byte
// every `slow_period`. A socket the server closed is opened again at the next tick (100 ms).
class HostileSockets {
 public:
  HostileSockets(int port, int silent, int slow, std::chrono::milliseconds slow_period)
      : port_(port), silent_(silent), slow_(slow), slow_period_(slow_period), thread_([this] { run(); }) {}
  ~HostileSockets() {
    stop_ = true;
    thread_.join();
  }
  int reopened() const { return reopened_; }
  int open_now() const { return open_now_; }

 private:
  void open(int& fd, bool slow) {
    fd = connect_to(port_, true);
    if (fd >= 0 && slow) ::send(fd, "GET / HTTP/1.1\r\nX-Slow: ", 24, MSG_NOSIGNAL);
  }
  void run() {
    std::vector<int> fds(static_cast<std::size_t>(silent_ + slow_), -1);
    for (std::size_t i = 0; i < fds.size(); ++i) open(fds[i], static_cast<int>(i) >= silent_);
    auto next_byte = Clock::now() + slow_period_;
    while (!stop_) {
      std::vector<pollfd> polled;
      for (const int fd : fds) polled.push_back({fd, POLLIN, 0});
      ::poll(polled.data(), polled.size(), 100);
      int open_count = 0;
      for (std::size_t i = 0; i < fds.size(); ++i) {
        char scratch[1024];
        if (fds[i] >= 0 && polled[i].revents != 0 && ::recv(fds[i], scratch, sizeof scratch, 0) <= 0) {
          ::close(fds[i]);
          fds[i] = -1;
        } else if (fds[i] < 0) {
          open(fds[i], static_cast<int>(i) >= silent_);
          ++reopened_;
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
  std::atomic<int> reopened_{0}, open_now_{0};
  std::thread thread_;
};

// `VIMG serve ARGS... --port 0` with stdout and stderr in files of `dir`; stopped with SIGTERM at
// the end.
class ServeChild {
 public:
  ServeChild(const std::string& vimg, std::vector<std::string> args, const std::string& dir, const std::string& assets) {
    out_ = dir + "/serve.stdout";
    const std::string err = dir + "/serve.stderr";
    pid_ = fork();
    if (pid_ == 0) {
      const int out_fd = ::open(out_.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
      const int err_fd = ::open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
      dup2(out_fd, STDOUT_FILENO);
      dup2(err_fd, STDERR_FILENO);
      setenv("VIMG_WEB_ASSETS", assets.c_str(), 1);
      args.insert(args.begin(), {vimg, "serve"});
      args.insert(args.end(), {"--port", "0"});
      std::vector<char*> argv;
      for (std::string& a : args) argv.push_back(a.data());
      argv.push_back(nullptr);
      execv(vimg.c_str(), argv.data());
      _exit(127);
    }
  }
  ~ServeChild() {
    kill(pid_, SIGTERM);
    waitpid(pid_, nullptr, 0);
  }
  ServeChild(const ServeChild&) = delete;
  ServeChild& operator=(const ServeChild&) = delete;

  const std::string& out_file() const { return out_; }

 private:
  pid_t pid_ = -1;
  std::string out_;
};

}  // namespace vimg::bench
