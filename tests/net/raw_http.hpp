#pragma once
// A client that sends exactly the bytes a test gives (no normalisation of "/../", no encoding, any
// method) to 127.0.0.1:PORT and reads what comes back: how an attacker or curl --path-as-is talks.
// Reads block; each wait ends after kHangBound at the latest, which only bounds a hang (a broken
// server, or an event that never comes while keep-alive comments do), it times nothing.
// The raw-socket helpers of the server's tests, of bench/study_load (with tests/net/hostile_clients.hpp)
// and of fuzz/http_connection_fuzz.cpp; a signal (libFuzzer's timer) interrupts none of their calls.
#include <arpa/inet.h>
#include <fcntl.h>
#include <poll.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cctype>
#include <chrono>
#include <cerrno>
#include <cstdint>
#include <map>
#include <string>
#include <thread>

namespace vimg::test {

// A TCP connection to 127.0.0.1:PORT (non-blocking once connected when asked); -1 when it fails.
inline int connect_loopback(int port, bool non_blocking = false) {
  const int fd = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
  if (fd < 0) return -1;
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_port = htons(static_cast<std::uint16_t>(port));
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  if (::connect(fd, reinterpret_cast<const sockaddr*>(&address), sizeof address) != 0) {
    // Interrupted by a signal, the connect goes on: its outcome is known once the socket is writable.
    int error = errno;
    if (error == EINTR) {
      pollfd p{fd, POLLOUT, 0};
      while (::poll(&p, 1, -1) < 0 && errno == EINTR) {}
      socklen_t length = sizeof error;
      if (::getsockopt(fd, SOL_SOCKET, SO_ERROR, &error, &length) != 0) error = errno;
    }
    if (error != 0) {
      ::close(fd);
      return -1;
    }
  }
  if (non_blocking) ::fcntl(fd, F_SETFL, O_NONBLOCK);
  return fd;
}

inline constexpr std::chrono::seconds kHangBound{60};

// Waits until condition() holds (a state, not a time); false only after kHangBound (a hang).
template <class Condition>
bool wait_for(Condition condition) {
  const auto give_up = std::chrono::steady_clock::now() + kHangBound;
  while (!condition()) {
    if (std::chrono::steady_clock::now() > give_up) return false;
    std::this_thread::yield();
  }
  return true;
}

struct HttpResponse {
  int status = 0;  // 0: no response (the connection closed or failed first)
  std::map<std::string, std::string> headers;  // names in lower case
  std::string body;
};

class RawConnection {
 public:
  explicit RawConnection(int port) : fd_(connect_loopback(port)), connected_(fd_ >= 0) {}
  ~RawConnection() { if (fd_ >= 0) close(fd_); }
  RawConnection(const RawConnection&) = delete;
  RawConnection& operator=(const RawConnection&) = delete;

  bool connected() const { return connected_; }
  int fd() const { return fd_; }

  bool send_all(const std::string& bytes) {
    std::size_t sent = 0;
    while (sent < bytes.size()) {
      const ssize_t n = ::send(fd_, bytes.data() + sent, bytes.size() - sent, MSG_NOSIGNAL);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) return false;
      sent += static_cast<std::size_t>(n);
    }
    return true;
  }

  // Reads until `text` has arrived (true) or the connection ends (false); everything read is in received().
  bool read_until(const std::string& text) {
    const auto give_up = std::chrono::steady_clock::now() + kHangBound;
    while (received_.find(text) == std::string::npos) {
      if (!read_some(give_up)) return false;
    }
    return true;
  }
  // Reads until `text` has arrived `count` times (each SSE message comes in a chunk of its own, so
  // a message is never split by the chunked framing).
  bool read_until_count(const std::string& text, int count) {
    const auto give_up = std::chrono::steady_clock::now() + kHangBound;
    while (count_of(text) < count) {
      if (!read_some(give_up)) return false;
    }
    return true;
  }
  int count_of(const std::string& text) const {
    int n = 0;
    for (std::size_t at = received_.find(text); at != std::string::npos; at = received_.find(text, at + text.size())) ++n;
    return n;
  }
  // Reads until the peer closes the connection: true then; false when the bound or an error ended
  // the wait instead (a server that never closes).
  bool read_to_end(std::chrono::milliseconds bound = kHangBound) {
    const auto give_up = std::chrono::steady_clock::now() + bound;
    while (read_some(give_up)) {}
    return closed_by_peer_;
  }
  // The peer has ended the connection, in order or with a reset (not: the bound ended the wait).
  bool ended_by_peer() const { return closed_by_peer_ || reset_by_peer_; }
  const std::string& received() const { return received_; }

 private:
  // False at the end of the stream, on an error, or at `give_up`.
  bool read_some(std::chrono::steady_clock::time_point give_up) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(give_up - std::chrono::steady_clock::now());
    if (left.count() <= 0) return false;
    pollfd p{fd_, POLLIN, 0};
    const int ready = poll(&p, 1, static_cast<int>(left.count()));
    if (ready < 0 && errno == EINTR) return read_some(give_up);
    if (ready <= 0) return false;
    char buffer[4096];
    ssize_t n = 0;
    do {
      n = ::recv(fd_, buffer, sizeof buffer, 0);
    } while (n < 0 && errno == EINTR);
    if (n == 0) closed_by_peer_ = true;
    if (n < 0) reset_by_peer_ = true;
    if (n <= 0) return false;
    received_.append(buffer, static_cast<std::size_t>(n));
    return true;
  }

  int fd_ = -1;
  bool connected_ = false;
  bool closed_by_peer_ = false;  // recv() returned 0: the orderly end of the stream
  bool reset_by_peer_ = false;   // recv() failed (a reset)
  std::string received_;
};

inline HttpResponse parse_response(const std::string& raw) {
  HttpResponse response;
  const std::size_t head_end = raw.find("\r\n\r\n");
  if (raw.rfind("HTTP/1.", 0) != 0 || head_end == std::string::npos) return response;
  response.status = std::stoi(raw.substr(9, 3));
  std::size_t line_start = raw.find("\r\n") + 2;
  while (line_start < head_end) {
    const std::size_t line_end = raw.find("\r\n", line_start);
    const std::string line = raw.substr(line_start, line_end - line_start);
    const std::size_t colon = line.find(':');
    std::string name = line.substr(0, colon);
    for (char& c : name) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    response.headers[name] = colon == std::string::npos ? "" : line.substr(line.find_first_not_of(' ', colon + 1));
    line_start = line_end + 2;
  }
  response.body = raw.substr(head_end + 4);
  return response;
}

// One request with "Connection: close" sent as given; the whole response.
inline HttpResponse exchange(int port, const std::string& method, const std::string& target,
                             const std::string& extra_headers = "", const std::string& body = "") {
  RawConnection connection(port);
  if (!connection.connected()) return {};
  connection.send_all(method + " " + target + " HTTP/1.1\r\nHost: localhost\r\nConnection: close\r\n" + extra_headers +
                      "\r\n" + body);
  connection.read_to_end();
  return parse_response(connection.received());
}

}  // namespace vimg::test
