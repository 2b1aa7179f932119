#include "web/server/web_server.hpp"

#include <atomic>
#include <cstdio>
#include <utility>

#include "storage/read_file.hpp"
#include "web/server/content_type.hpp"
#include "web/server/event_stream.hpp"
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

}  // namespace

struct WebServer::Impl {
  explicit Impl(WebServerOptions o) : options(std::move(o)), engine(routes()) {}
  WebServerOptions options;
  fs::path site_root;  // canonical
  EventBroadcaster events;
  HttpEngine engine;
  std::atomic<bool> running{false};

  HttpRoutes routes() {
    HttpRoutes r;
    r.refuse = [this](const HttpRequest& request) { return refusal(request); };
    r.respond = [this](const HttpRequest& request) { return respond(request); };
    r.log = [this](const HttpRequest& request, const HttpReply& reply) {
      const std::size_t bytes = request.method == "HEAD" || reply.event_stream ? 0 : reply.body.size();
      log(loggable(request.method) + " " + loggable(request.path.empty() ? request.target : request.path) + " " +
          std::to_string(reply.status) + " " + std::to_string(bytes));
    };
    r.events = &events;
    r.max_body_bytes = kMaxRequestBodyBytes;
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

  HttpReply respond(const HttpRequest& request) {
    if (request.method == "POST") return serve_api(request);
    if (request.path == "/events") return serve_events(request);
    if (options.api && request.path.rfind("/api/", 0) == 0) return serve_api(request);
    return serve_file(request);
  }

  HttpReply serve_api(const HttpRequest& request) const {
    const ApiReply api = options.api(ApiRequest{request.method, request.path, request.query, request.host,
                                                request.origin, request.key, request.content_type, request.body});
    HttpReply reply;
    reply.status = api.status;
    reply.content_type = api.content_type;
    reply.body = api.body;
    return reply;
  }

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
    const std::int64_t cursor = events.open_stream();
    if (cursor < 0) return text_reply(503, "too many open event streams (at most " + std::to_string(kMaxEventStreams) + ")");
    reply.headers.emplace_back("X-Accel-Buffering", "no");
    reply.event_stream = true;
    reply.stream_cursor = cursor;
    // The page (or a test) knows from this comment that it will get every later save.
    reply.body = ": connected\nretry: 1000\n\n";
    return reply;
  }

  HttpReply serve_file(const HttpRequest& request) const {
    const SiteLookup lookup = find_site_file(site_root, request.path);
    if (lookup.status == SiteLookupStatus::forbidden) return text_reply(403, "forbidden: " + lookup.reason);
    if (lookup.status == SiteLookupStatus::not_found) return text_reply(404, "not found");
    FileReadResult read = read_regular_file(lookup.file, kMaxServedFileBytes, FinalSymlink::refuse);
    if (!read.bytes) {
      log("cannot read " + lookup.file.string() + ": " + read.error);
      return text_reply(500, "the file cannot be read");
    }
    HttpReply reply;
    reply.content_type = content_type_of(lookup.file);
    reply.body = std::move(*read.bytes);
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
  if (auto problem = s.engine.start(endpoint)) return problem;
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

void WebServer::stop() {
  Impl& s = *impl_;
  if (!s.running.exchange(false)) return;
  s.events.close();
  s.engine.stop();
}

}  // namespace vimg::web
