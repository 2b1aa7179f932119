#include "web/server/web_server.hpp"

#include <httplib.h>

#include <atomic>
#include <utility>
#include <cstdio>
#include <thread>

#include "storage/read_file.hpp"
#include "web/server/content_type.hpp"
#include "web/server/event_stream.hpp"
#include "web/server/site_path.hpp"

namespace vimg::web {

namespace fs = std::filesystem;

namespace {

// How often an idle event stream sends a comment, so that a page that has gone is noticed.
constexpr std::chrono::seconds kEventKeepAlive{15};
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

void set_text(httplib::Response& res, int status, const std::string& text) {
  res.status = status;
  res.set_content(text + "\n", "text/plain; charset=utf-8");
}

}  // namespace

struct WebServer::Impl {
  explicit Impl(WebServerOptions o) : options(std::move(o)) {}
  WebServerOptions options;
  fs::path site_root;  // canonical
  std::unique_ptr<httplib::Server> server_owned;  // an SSLServer with TLS
  httplib::Server& server = make_server();
  EventBroadcaster events;
  std::thread listener;
  std::atomic<bool> running{false};
  std::atomic<bool> listen_ended{false};
  int port = 0;

  httplib::Server& make_server() {
    if (options.tls_cert_pem.empty() && options.tls_key_pem.empty()) {
      server_owned = std::make_unique<httplib::Server>();
    } else {
      server_owned = std::make_unique<httplib::SSLServer>(options.tls_cert_pem.c_str(), options.tls_key_pem.c_str());
    }
    return *server_owned;
  }

  // The TLS certificate and key could not be read (start() says so).
  bool tls_invalid() const {
    if (options.tls_cert_pem.empty() && options.tls_key_pem.empty()) return false;
    return !static_cast<const httplib::SSLServer&>(*server_owned).is_valid();
  }

  bool api_post_path(const std::string& path) const {
    if (!options.api) return false;
    for (const std::string& p : options.api_post_paths) {
      if (p == path) return true;
    }
    return false;
  }

  void serve_api(const httplib::Request& req, httplib::Response& res) const {
    ApiRequest request;
    request.method = req.method;
    request.path = req.path;
    const std::size_t question = req.target.find('?');
    if (question != std::string::npos) request.query = req.target.substr(question + 1);
    request.host = req.get_header_value("Host");
    request.origin = req.get_header_value("Origin");
    request.key = req.get_header_value("X-Vimg-Key");
    request.content_type = req.get_header_value("Content-Type");
    request.body = req.body;
    const ApiReply reply = options.api(request);
    res.status = reply.status;
    res.set_content(reply.body, reply.content_type);
  }

  void log(const std::string& line) const {
    if (options.log_line) {
      options.log_line(line);
    } else {
      std::fprintf(stderr, "%s\n", line.c_str());
    }
  }

  void serve_events(const httplib::Request& req, httplib::Response& res) {
    if (req.method == "HEAD") {
      res.set_content("", "text/event-stream");
      return;
    }
    const std::int64_t cursor = events.open_stream();
    if (cursor < 0) {
      set_text(res, 503, "too many open event streams (at most " + std::to_string(kMaxEventStreams) + ")");
      return;
    }
    auto state = std::make_shared<std::int64_t>(cursor);
    auto greeted = std::make_shared<bool>(false);
    res.set_header("X-Accel-Buffering", "no");
    res.set_chunked_content_provider(
        "text/event-stream",
        [this, state, greeted](std::size_t, httplib::DataSink& sink) {
          if (!*greeted) {
            *greeted = true;  // the page (or a test) knows from this comment that it will get every later save
            static constexpr std::string_view kHello = ": connected\nretry: 1000\n\n";
            return sink.write(kHello.data(), kHello.size());
          }
          const EventBroadcaster::Wait wait = events.wait_after(*state, kEventKeepAlive);
          if (wait.closed) return false;
          const std::string text = wait.text.empty() ? std::string(": keep-alive\n\n") : wait.text;
          return sink.write(text.data(), text.size());
        },
        [this](bool) { events.close_stream(); });
  }

  void serve_file(const httplib::Request& req, httplib::Response& res) const {
    const SiteLookup lookup = find_site_file(site_root, req.path);
    if (lookup.status == SiteLookupStatus::forbidden) return set_text(res, 403, "forbidden: " + lookup.reason);
    if (lookup.status == SiteLookupStatus::not_found) return set_text(res, 404, "not found");
    const FileReadResult read = read_regular_file(lookup.file, kMaxServedFileBytes, FinalSymlink::refuse);
    if (!read.bytes) {
      log("cannot read " + lookup.file.string() + ": " + read.error);
      return set_text(res, 500, "the file cannot be read");
    }
    res.status = 200;
    res.set_content(*read.bytes, content_type_of(lookup.file));
  }

  void configure() {
    server.new_task_queue = [] { return new httplib::ThreadPool(kServerWorkerThreads); };
    server.set_payload_max_length(kMaxRequestBodyBytes);
    server.set_keep_alive_timeout(1);  // an idle connection holds a worker; stop() waits for it
    server.set_default_headers({{"Cache-Control", "no-store"}, {"X-Content-Type-Options", "nosniff"}});
    server.set_pre_routing_handler([this](const httplib::Request& req, httplib::Response& res) {
      if (req.method == "GET" || req.method == "HEAD") return httplib::Server::HandlerResponse::Unhandled;
      if (req.method == "POST" && api_post_path(req.path)) return httplib::Server::HandlerResponse::Unhandled;
      set_text(res, 405, "method not allowed: this server is read-only (GET and HEAD)");
      res.set_header("Allow", "GET, HEAD");
      res.set_header("Connection", "close");  // a body, if any, is never read
      return httplib::Server::HandlerResponse::Handled;
    });
    server.Get("[\\s\\S]*", [this](const httplib::Request& req, httplib::Response& res) {
      if (req.path == "/events") {
        serve_events(req, res);
      } else if (options.api && req.path.rfind("/api/", 0) == 0) {
        serve_api(req, res);
      } else {
        serve_file(req, res);
      }
    });
    server.Post("[\\s\\S]*", [this](const httplib::Request& req, httplib::Response& res) { serve_api(req, res); });
    server.set_logger([this](const httplib::Request& req, const httplib::Response& res) {
      const std::size_t bytes = req.method == "HEAD" ? 0 : res.body.size();
      log(loggable(req.method) + " " + loggable(req.path.empty() ? req.target : req.path) + " " +
          std::to_string(res.status) + " " + std::to_string(bytes));
    });
  }
};

WebServer::WebServer(WebServerOptions options) : impl_(std::make_unique<Impl>(std::move(options))) {
  impl_->configure();
}

WebServer::~WebServer() { stop(); }

std::optional<std::string> WebServer::start() {
  Impl& s = *impl_;
  if (s.running) return "the server is already running";
  std::error_code ec;
  s.site_root = fs::canonical(s.options.site_dir, ec);
  if (ec || !fs::is_directory(s.site_root)) return s.options.site_dir.string() + ": not a folder that can be served";
  if (s.tls_invalid()) {
    return s.options.tls_cert_pem.string() + ", " + s.options.tls_key_pem.string() +
           ": cannot be read as a PEM certificate and its private key";
  }
  if (s.options.port == 0) {
    s.port = s.server.bind_to_any_port(s.options.host);
  } else {
    s.port = s.server.bind_to_port(s.options.host, s.options.port) ? s.options.port : -1;
  }
  if (s.port <= 0) {
    return "cannot listen on " + s.options.host + ":" + std::to_string(s.options.port) +
           " (the port is in use, or the address is not this machine's)";
  }
  s.running = true;
  s.listen_ended = false;
  s.listener = std::thread([&s] {
    s.server.listen_after_bind();
    s.listen_ended = true;
  });
  return std::nullopt;
}

int WebServer::port() const { return impl_->port; }

bool WebServer::running() const { return impl_->running && !impl_->listen_ended; }

void WebServer::publish_image_changed(const std::string& name) {
  impl_->events.publish(format_event_message("image", name));
}

int WebServer::open_event_streams() const { return impl_->events.open_streams(); }

void WebServer::stop() {
  Impl& s = *impl_;
  if (!s.running.exchange(false)) return;
  s.events.close();
  s.server.stop();
  if (s.listener.joinable()) s.listener.join();
}

}  // namespace vimg::web
