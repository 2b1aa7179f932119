// Raw bytes through the real server (web/server/web_server.hpp): Beast's parser, the connection's
// state machine (web/server/http_connection.hpp: header, refusal, body, 100-continue, the route's
// queue and the departure watch, the reply, keep-alive, pipelining, event streams, the close) and
// the routes behind it (the site's files, a stub API), over a real loopback socket (the tests'
// client, tests/net/raw_http.hpp). The first byte
// chooses:
//   'P'  the rest is a URL path for the site-path lookup (web/server/site_path.hpp) alone: a file
//        found is a regular file inside the site, and no path with a ".." segment finds one;
//   else the whole input is sent as one client's bytes, then the client half-closes and reads.
// Properties: the server closes the connection within kCloseBound (every client that has
// half-closed is ended: nothing waits on it); what it sends is a sequence of replies, each
// "HTTP/1.1 NNN" with a status the server can give (never 500: no route here fails); nothing
// crashes, leaks or trips UBSan. The server's deadlines are shrunk so that an input cannot hold it.
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "tests/net/raw_http.hpp"
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
    // A screen as the study's (refusals on the network thread, before the route waits for anything).
    options.api_screen = [](const ApiRequest& request) -> std::optional<ApiReply> {
      if (request.body.size() > 64) return body_reply(429, "text/plain", "too many");
      return std::nullopt;
    };
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
    case 100: case 200: case 400: case 403: case 404: case 405: case 413: case 414: case 429: case 503: return true;
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
  vimg::test::RawConnection client(port);
  if (!client.connected()) std::abort();
  client.send_all(std::string(input));  // false when the server closed first (it refused the request)
  ::shutdown(client.fd(), SHUT_WR);
  client.read_to_end(kCloseBound);
  if (!client.ended_by_peer()) {  // never closed
    const HttpEngineCounts c = fixture().server->counts();
    std::fprintf(stderr, "not closed within %lld ms; received %zu bytes; server: %d open, %ld queued, %ld dropped\n",
                 static_cast<long long>(kCloseBound.count()), client.received().size(), c.open_connections,
                 c.routes_queued, c.routes_dropped);
    std::size_t fds = 0;
    for ([[maybe_unused]] const auto& entry : fs::directory_iterator("/proc/self/fd")) ++fds;
    std::fprintf(stderr, "%zu descriptors open; %ld refused busy, %ld closed unanswered\n", fds, c.refused_busy, c.closed_unanswered);
    std::abort();
  }
  // Closed with a reset: the server has closed its side already, and a million inputs leave no
  // million ports in TIME_WAIT.
  const linger reset{1, 0};
  ::setsockopt(client.fd(), SOL_SOCKET, SO_LINGER, &reset, sizeof reset);
  check_replies(client.received());
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
