// Raw bytes through the real server (web/server/web_server.hpp): Beast's parser, the connection's
// state machine (web/server/http_connection.hpp: header, refusal, body, 100-continue, the route's
// queue and the departure watch, the reply, keep-alive, pipelining, event streams, the close) and
// the routes behind it (the site's files, a stub API), over a real loopback socket. The first byte
// chooses:
//   'P'  the rest is a URL path for the site-path lookup (web/server/site_path.hpp) alone: a file
//        found is a regular file inside the site, and no path with a ".." segment finds one;
//   else the whole input is sent as one client's bytes, then the client half-closes and reads.
// Properties: the server closes the connection within kCloseBound (every client that has
// half-closed is ended: nothing waits on it); what it sends is a sequence of replies, each
// "HTTP/1.1 NNN" with a status the server can give (never 500: no route here fails); nothing
// crashes, leaks or trips UBSan. The server's deadlines are shrunk so that an input cannot hold it.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <string_view>

#include "web/server/site_path.hpp"
#include "web/server/web_server.hpp"

namespace {

namespace fs = std::filesystem;
using namespace vimg::web;

constexpr std::chrono::milliseconds kCloseBound{5000};

struct Fixture {
  fs::path root, site;
  std::unique_ptr<WebServer> server;

  Fixture() {
    root = fs::temp_directory_path() / ("vimg-http-fuzz-" + std::to_string(::getpid()));
    fs::remove_all(root);
    site = root / "site";
    fs::create_directories(site / "images");
    std::ofstream(site / "index.html") << "<!doctype html><title>site</title>";
    std::ofstream(site / "vimg.wasm", std::ios::binary) << std::string("\0asm\1\0\0\0", 8);
    std::ofstream(site / "images" / "smiley.vsc") << "VSC1";
    std::ofstream(root / "secret.txt") << "secret";
    fs::create_symlink(root / "secret.txt", site / "out.txt");
    site = fs::canonical(site);
    WebServerOptions options;
    options.site_dir = site;
    options.log_line = [](const std::string&) {};
    options.api = [](const ApiRequest& request) {
      if (request.path == "/api/answer") return body_reply(200, "application/json", "{\"bytes\": " + std::to_string(request.body.size()) + "}");
      return body_reply(404, "text/plain", "not found");
    };
    options.api_post_paths = {"/api/answer"};
    options.limits.header_deadline = std::chrono::milliseconds(1000);
    options.limits.body_deadline = std::chrono::milliseconds(1000);
    options.limits.closing_deadline = std::chrono::milliseconds(200);
    options.limits.write_deadline = std::chrono::milliseconds(1000);
    options.limits.event_stream_lifetime = std::chrono::milliseconds(200);
    server = std::make_unique<WebServer>(options);
    if (server->start()) std::abort();
  }
  ~Fixture() {
    server.reset();
    std::error_code ec;
    fs::remove_all(root, ec);
  }
};

Fixture& fixture() {
  static Fixture f;
  return f;
}

bool known_status(int status) {
  switch (status) {
    case 100: case 200: case 400: case 403: case 404: case 405: case 413: case 414: case 503: return true;
    default: return false;
  }
}

// The replies in `bytes`: they start at the first byte, and every "HTTP/1.1 " is a reply's head
// (no body the server sends here holds it: the site's files, the stub's JSON and the server's
// own texts, which never echo the request), with a status the server can give.
void check_replies(const std::string& bytes) {
  if (bytes.empty()) return;
  if (bytes.rfind("HTTP/1.1 ", 0) != 0) std::abort();
  for (std::size_t at = 0; at != std::string::npos; at = bytes.find("HTTP/1.1 ", at + 1)) {
    if (at + 13 > bytes.size() || bytes[at + 12] != ' ') std::abort();
    if (!known_status(std::atoi(bytes.substr(at + 9, 3).c_str()))) std::abort();
  }
}

void exchange(int port, std::string_view input) {
  const int fd = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
  if (fd < 0) return;
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_port = htons(static_cast<std::uint16_t>(port));
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  if (::connect(fd, reinterpret_cast<const sockaddr*>(&address), sizeof address) != 0) {
    if (errno != EINTR) std::abort();
    pollfd p{fd, POLLOUT, 0};  // interrupted by libFuzzer's timer signal: the connect goes on
    while (::poll(&p, 1, -1) < 0 && errno == EINTR) {}
  }
  std::size_t sent = 0;
  while (sent < input.size()) {
    const ssize_t n = ::send(fd, input.data() + sent, input.size() - sent, MSG_NOSIGNAL);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;  // the server closed first (it refused the request)
    sent += static_cast<std::size_t>(n);
  }
  ::shutdown(fd, SHUT_WR);
  std::string received;
  const auto give_up = std::chrono::steady_clock::now() + kCloseBound;
  for (;;) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(give_up - std::chrono::steady_clock::now());
    pollfd p{fd, POLLIN, 0};
    const int ready = left.count() <= 0 ? 0 : ::poll(&p, 1, static_cast<int>(left.count()));
    if (ready < 0 && errno == EINTR) continue;  // libFuzzer's timer signal
    if (ready <= 0) {  // never closed
      const HttpEngineCounts c = fixture().server->counts();
      std::fprintf(stderr, "not closed within %lld ms; received %zu bytes; server: %d open, %ld queued, %ld dropped\n",
                   static_cast<long long>(kCloseBound.count()), received.size(), c.open_connections, c.routes_queued,
                   c.routes_dropped);
      std::size_t fds = 0;
      for ([[maybe_unused]] const auto& entry : fs::directory_iterator("/proc/self/fd")) ++fds;
      std::fprintf(stderr, "%zu descriptors open; %ld refused busy, %ld closed unanswered\n", fds, c.refused_busy, c.closed_unanswered);
      std::abort();
    }
    char buffer[4096];
    const ssize_t n = ::recv(fd, buffer, sizeof buffer, 0);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;  // closed (orderly, or reset after a refusal)
    received.append(buffer, static_cast<std::size_t>(n));
  }
  // Closed with a reset: the server has closed its side already, and a million inputs leave no
  // million ports in TIME_WAIT.
  const linger reset{1, 0};
  ::setsockopt(fd, SOL_SOCKET, SO_LINGER, &reset, sizeof reset);
  ::close(fd);
  check_replies(received);
}

void check_lookup(const fs::path& site, std::string_view path) {
  const SiteLookup lookup = find_site_file(site, path);
  if (lookup.status != SiteLookupStatus::found) return;
  const std::string found = lookup.file.string();
  if (found.rfind(site.string() + "/", 0) != 0) std::abort();
  std::error_code ec;
  if (!fs::is_regular_file(fs::symlink_status(lookup.file, ec))) std::abort();
  const std::string padded = "/" + std::string(path) + "/";
  if (padded.find("/../") != std::string::npos || padded.find("/./") != std::string::npos) std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  Fixture& f = fixture();
  const std::string_view input(reinterpret_cast<const char*>(data), size);
  if (!input.empty() && input.front() == 'P') {
    check_lookup(f.site, input.substr(1));
    return 0;
  }
  exchange(f.server->port(), input);
  return 0;
}
