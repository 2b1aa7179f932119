#pragma once
// The network side of the server (web/server/web_server.hpp): event-driven HTTP/1.1 on Boost.Beast
// and Asio, so that a connection that waits costs a few kilobytes and no thread. One thread runs
// every socket; the routes run on kRouteWorkerThreads workers and hand their reply back. Each
// connection is held to the bounds of web/server/http_message.hpp: its header within
// kHeaderDeadline of connecting (or of its last reply) however slowly it trickles, its body
// within kBodyDeadline and kMaxRequestBodyBytes, at most kMaxConnections at once (one more is
// answered 503 and closed at once). There is no bound per address: a lab's participants share one.
// Beast's templates are compiled in http_engine.cpp only.
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "web/server/event_stream.hpp"
#include "web/server/http_message.hpp"

namespace vimg::web {

struct HttpRoutes {
  // On the network thread, once a request's header is read: a reply at once (its body is never
  // read), or nothing to read the body (up to `max_body_bytes`) and call respond().
  std::function<std::optional<HttpReply>(const HttpRequest&)> refuse;
  // On a worker: the reply. A reply with event_stream opened a stream of `events` (its cursor).
  std::function<HttpReply(const HttpRequest&)> respond;
  // On the network thread: every reply sent, or refused before a route saw it.
  std::function<void(const HttpRequest&, const HttpReply&)> log;
  EventBroadcaster* events = nullptr;
  std::size_t max_body_bytes = 0;
};

struct HttpEndpoint {
  std::string host;
  int port = 0;  // 0: any free port
  std::string tls_cert_pem, tls_key_pem;  // both empty: plain HTTP
};

class HttpEngine {
 public:
  explicit HttpEngine(HttpRoutes routes);
  ~HttpEngine();  // stop()
  HttpEngine(const HttpEngine&) = delete;
  HttpEngine& operator=(const HttpEngine&) = delete;

  // Reads the certificate (with TLS), binds and starts the threads; the problem otherwise.
  std::optional<std::string> start(const HttpEndpoint& endpoint);
  int port() const;
  int max_connections() const;
  // Each open event stream sends what was published since its cursor.
  void wake_event_streams();
  // Closes the listening socket and every connection, lets the running routes end, joins. Idempotent.
  void stop();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace vimg::web
