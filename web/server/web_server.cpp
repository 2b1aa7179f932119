#include "web/server/web_server.hpp"

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <utility>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "storage/read_file.hpp"
#include "web/server/content_type.hpp"
#include "web/server/event_stream.hpp"
#include "web/server/file_copies.hpp"
#include "web/server/http_engine.hpp"
#include "web/server/site_path.hpp"

namespace vimg::web {

namespace fs = std::filesystem;

namespace {

constexpr std::size_t kMaxLoggedPathChars = 200;

// The path as the log shows it: control characters and non-ASCII bytes as \xHH, cut at
// kMaxLoggedPathChars, so that a request cannot forge or flood log lines.
std::string loggable(const std::string& text) {
  std::string out;
  for (const char c : text.substr(0, kMaxLoggedPathChars)) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte < 0x20 || byte >= 0x7f || c == '\\') {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\x%02x", byte);
      out += escaped;
    } else {
      out += c;
    }
  }
  if (text.size() > kMaxLoggedPathChars) out += "...";
  return out;
}

// A file opened for a reply (never blocking, never through a final symbolic link), closed at the end.
struct OpenFile {
  explicit OpenFile(const fs::path& path) : fd(::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK | O_NOCTTY | O_NOFOLLOW)) {}
  ~OpenFile() {
    if (fd >= 0) ::close(fd);
  }
  OpenFile(const OpenFile&) = delete;
  OpenFile& operator=(const OpenFile&) = delete;
  int fd;
};

FileVersion version_of(const struct stat& st) {
  return {st.st_dev, st.st_ino, static_cast<std::uint64_t>(st.st_size),
          static_cast<std::int64_t>(st.st_mtim.tv_sec) * 1000000000 + st.st_mtim.tv_nsec,
          static_cast<std::int64_t>(st.st_ctim.tv_sec) * 1000000000 + st.st_ctim.tv_nsec};
}

}  // namespace

struct WebServer::Impl {
  explicit Impl(WebServerOptions o) : options(std::move(o)), copies(options.limits.reply_budget_bytes), engine(routes()) {}
  WebServerOptions options;
  fs::path site_root;  // canonical
  EventBroadcaster events;
  FileCopies copies;  // before the engine: the replies it still holds give their bytes back to it
  HttpEngine engine;
  std::atomic<bool> running{false};

  HttpRoutes routes() {
    HttpRoutes r;
    r.refuse = [this](const HttpRequest& request) { return refusal(request); };
    r.respond = [this](const HttpRequest& request) { return respond(request); };
    if (options.api && options.api_screen) {
      r.screen = [this](const HttpRequest& request) -> std::optional<HttpReply> {
        if (!to_api(request)) return std::nullopt;
        return options.api_screen(request);
      };
    }
    r.log = [this](const HttpRequest& request, const HttpReply& reply) {
      const std::size_t bytes = request.method == "HEAD" || reply.event_stream ? 0 : reply.body_bytes().size();
      log(loggable(request.method) + " " + loggable(request.path.empty() ? request.target : request.path) + " " +
          std::to_string(reply.status) + " " + std::to_string(bytes));
    };
    r.log_failure = [this](const HttpRequest& request, const std::string& what) {
      log(loggable(request.method) + " " + loggable(request.path.empty() ? request.target : request.path) +
          ": failed: " + loggable(what));
    };
    r.files_held = options.api_files_held;
    if (options.api) {
      r.passed_fields = {kApiKeyField};
      r.client_field = kApiKeyField;
    }
    r.events = &events;
    r.max_body_bytes = kMaxRequestBodyBytes;
    r.limits = options.limits;
    return r;
  }

  bool api_post_path(const std::string& path) const {
    if (!options.api) return false;
    for (const std::string& p : options.api_post_paths) {
      if (p == path) return true;
    }
    return false;
  }

  // GET and HEAD, and POST of the API's paths, go on; anything else is 405 (its body never read).
  std::optional<HttpReply> refusal(const HttpRequest& request) const {
    if (request.method == "GET" || request.method == "HEAD") return std::nullopt;
    if (request.method == "POST" && api_post_path(request.path)) return std::nullopt;
    HttpReply reply = text_reply(405, "method not allowed: this server is read-only (GET and HEAD)");
    reply.headers.emplace_back("Allow", "GET, HEAD");
    reply.close = true;
    return reply;
  }

  // POST (refusal() lets through the API's paths only) and, with an API, /api/...
  bool to_api(const HttpRequest& request) const {
    return request.method == "POST" || (options.api && request.path.rfind("/api/", 0) == 0);
  }

  HttpReply respond(const HttpRequest& request) {
    if (to_api(request)) return serve_api(request);
    if (request.path == "/events" && !options.api) return serve_events(request);
    return serve_file(request);
  }

  HttpReply serve_api(const HttpRequest& request) const { return options.api(request); }

  void log(const std::string& line) const {
    if (options.log_line) {
      options.log_line(line);
    } else {
      std::fprintf(stderr, "%s\n", line.c_str());
    }
  }

  HttpReply serve_events(const HttpRequest& request) {
    HttpReply reply;
    reply.content_type = "text/event-stream";
    if (request.method == "HEAD") return reply;
    const std::int64_t cursor = events.open_stream(last_event_id(request));
    if (cursor < 0) {
      // Every place is taken: a 503 would end the page's EventSource for good; a stream that ends
      // after its retry hint makes it try again then.
      reply.body = ": every place is taken (at most " + std::to_string(kMaxEventStreams) + " pages)\nretry: " +
                   std::to_string(kEventStreamFullRetry.count()) + "\n\n";
      reply.close = true;
      return reply;
    }
    reply.headers.emplace_back("X-Accel-Buffering", "no");
    reply.event_stream = true;
    reply.stream_cursor = cursor;
    // The page (or a test) knows from this comment that it will get every later save.
    reply.body = ": connected\nretry: 1000\n\n";
    return reply;
  }

  static std::optional<std::int64_t> last_event_id(const HttpRequest& request) {
    if (request.last_event_id.empty() || request.last_event_id.size() > 18) return std::nullopt;
    std::int64_t id = 0;
    for (const char c : request.last_event_id) {
      if (c < '0' || c > '9') return std::nullopt;
      id = id * 10 + (c - '0');
    }
    return id;
  }

  // The file's shared copy (read through storage/read_file.hpp's bounded read when no reply holds
  // one of this version); HEAD only stats it.
  HttpReply serve_file(const HttpRequest& request) {
    const SiteLookup lookup = find_site_file(site_root, request.path);
    if (lookup.status == SiteLookupStatus::forbidden) return text_reply(403, "forbidden: " + lookup.reason);
    if (lookup.status == SiteLookupStatus::not_found) return text_reply(404, "not found");
    const auto cannot_read = [&](const std::string& why) {
      log("cannot read " + lookup.file.string() + ": " + why);
      return text_reply(500, "the file cannot be read");
    };
    const OpenFile file(lookup.file);
    struct stat st {};
    if (file.fd < 0 || ::fstat(file.fd, &st) != 0) return cannot_read(std::string("cannot open: ") + std::strerror(errno));
    if (!S_ISREG(st.st_mode)) return cannot_read("is not a regular file");
    if (static_cast<std::uint64_t>(st.st_size) > kMaxServedFileBytes) {
      return cannot_read("is larger than the limit (" + std::to_string(kMaxServedFileBytes) + " bytes)");
    }
    HttpReply reply;
    reply.content_type = content_type_of(lookup.file);
    if (request.method == "HEAD") {
      reply.head_only_bytes = static_cast<std::size_t>(st.st_size);
      return reply;
    }
    FileCopies::Copy copy = copies.acquire(lookup.file.string(), version_of(st), [&](std::string& error) {
      FileReadResult read = read_open_file(file.fd, kMaxServedFileBytes);
      error = read.error;
      return std::move(read.bytes);
    });
    if (copy.over_budget) {  // waits for room (the engine runs this again), then 503
      HttpReply busy = text_reply(503, "the server is busy (its reply budget is full); try again");
      busy.headers.emplace_back("Retry-After", "1");
      busy.wait_for_room = !copy.never_fits;
      return busy;
    }
    if (!copy.bytes) return cannot_read(copy.error);
    reply.shared_body = std::move(copy.bytes);
    return reply;
  }
};

WebServer::WebServer(WebServerOptions options) : impl_(std::make_unique<Impl>(std::move(options))) {}

WebServer::~WebServer() { stop(); }

std::optional<std::string> WebServer::start() {
  Impl& s = *impl_;
  if (s.running) return "the server is already running";
  std::error_code ec;
  s.site_root = fs::canonical(s.options.site_dir, ec);
  if (ec || !fs::is_directory(s.site_root)) return s.options.site_dir.string() + ": not a folder that can be served";
  const HttpEndpoint endpoint{s.options.host, s.options.port, s.options.tls_cert_pem.string(), s.options.tls_key_pem.string()};
  s.copies.on_change([&s] { s.engine.retry_room_waiters(); });
  if (auto problem = s.engine.start(endpoint)) {
    s.copies.on_change({});
    return problem;
  }
  s.running = true;
  return std::nullopt;
}

int WebServer::port() const { return impl_->engine.port(); }

bool WebServer::running() const { return impl_->running; }

void WebServer::publish_image_changed(const std::string& name) {
  impl_->events.publish(format_event_message("image", name));
  impl_->engine.wake_event_streams();
}

int WebServer::open_event_streams() const { return impl_->events.open_streams(); }

HttpEngineCounts WebServer::counts() const { return impl_->engine.counts(); }

std::size_t WebServer::reply_bytes_held() const { return impl_->copies.held_bytes(); }

void WebServer::stop() {
  Impl& s = *impl_;
  if (!s.running.exchange(false)) return;
  s.events.close();
  s.engine.stop();
  s.copies.on_change({});  // the copies still held (freed with the engine) call nothing
}

}  // namespace vimg::web
