#pragma once
// The clients of the study server's load run (bench/study_load.cpp): one HTTP request over a socket
// of its own with a bound, a participant's keep-alive connection and `vimg serve` as a child process
// whose printed URL gives the port. The raw sockets and the hostile clients (silent, or a header
// byte at a time, on a thread of their own) are the server tests' (tests/net/).
#include <fcntl.h>
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

#include "tests/net/hostile_clients.hpp"
#include "tests/net/raw_http.hpp"

namespace vimg::bench {

using Clock = std::chrono::steady_clock;

inline double ms_since(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

using test::connect_loopback;
using Reply = test::HttpResponse;  // status 0: no reply within the bound (refused, reset, or too slow)
using test::HostileClients;

// One request with Connection: close; the reply, read until the server closes, within `bound`.
inline Reply request(int port, const std::string& text, std::chrono::milliseconds bound) {
  test::RawConnection connection(port);
  if (!connection.connected() || !connection.send_all(text)) return {};
  connection.read_to_end(bound);
  return test::parse_response(connection.received());
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
      if (fd_ < 0) fd_ = connect_loopback(port_);
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
