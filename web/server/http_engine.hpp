#pragma once
// The network side of the server (web/server/web_server.hpp): event-driven HTTP/1.1 on Boost.Beast
// and Asio, so that a connection that waits costs a few kilobytes and no thread. One thread runs
// every socket; the routes run on workers and hand their reply back: the reading routes on
// kRouteWorkerThreads, the writing ones (POST) on kWriteWorkerThreads of their own, so a slow
// disk under an answer's fsync stalls no file, state or report. A route is run only while its
// client is there (a connection whose peer has closed, or half-closed, is dropped with its route
// not run); a route that throws answers 500 and the failure is logged with the request's path.
// Each connection is held to HttpLimits (web/server/http_message.hpp): its header within the
// header deadline of connecting (or of its last reply) however slowly it trickles, its body
// within the body deadline and max_body_bytes, at most the connection cap at once, shared with the
// files the routes hold (web/server/descriptor_budget.hpp); one more is answered 503 once its
// request head is read (web/server/busy_refusal.hpp). A request refused by HttpRoutes::screen is
// answered on the network thread before it waits for anything; one whose route found no room in
// the reply budget waits for room on the network thread (no worker, no reply bytes held), up to
// the limits' reply_budget_wait. There is no bound per address: a lab's
// participants share one. stop() is graceful: the routes accepted run to their end and their
// replies are sent, within the stop grace deadline. Beast's templates are compiled in
// http_engine.cpp only.
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "web/server/event_stream.hpp"
#include "web/server/http_message.hpp"

namespace vimg::web {

struct HttpRoutes {
  // On the network thread, once a request's header is read: a reply at once (its body is never
  // read), or nothing to read the body (up to `max_body_bytes`) and call respond().
  std::function<std::optional<HttpReply>(const HttpRequest&)> refuse;
  // On the network thread, once the whole request is read (its body too), before it waits for
  // anything (a worker, its client's turn, a lock behind it): a reply at once, or nothing to run
  // respond(). For the refusals that cost no file and no participant's lock (the study's rate
  // limit, a wrong key), so that a client flooding requests behind its own slow one is refused at
  // once instead of queueing. Empty: nothing is refused here. One that throws answers 500, as respond() does.
  std::function<std::optional<HttpReply>(const HttpRequest&)> screen;
  // On a worker: the reply. A reply with event_stream opened a stream of `events` (its cursor); one
  // with wait_for_room waits its turn to run again (retry_room_waiters()), or is sent after the wait.
  std::function<HttpReply(const HttpRequest&)> respond;
  // On the network thread: every reply sent, or refused before a route saw it.
  std::function<void(const HttpRequest&, const HttpReply&)> log;
  // On the network thread: a route that threw (the request, what it threw).
  std::function<void(const HttpRequest&, const std::string&)> log_failure;
  // From the network thread, at each connection accepted: the files the routes hold open for long
  // (participants' trial files), which come off the connections' share of the descriptors.
  std::function<int()> files_held;
  // Further header fields a route reads (the study's X-Vimg-Key), passed in HttpRequest::passed_fields.
  std::vector<std::string> passed_fields;
  // A header field that names a client (the study's key: one participant): the routes of one
  // value run one at a time on each pool, the others waiting on the network thread, so that one
  // client's concurrent requests hold at most one worker of each pool (never every reading worker
  // behind its own answer's lock). Empty: no such field.
  std::string client_field;
  EventBroadcaster* events = nullptr;
  std::size_t max_body_bytes = 0;
  HttpLimits limits;
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
  // The connections served at once with no file held (the limits' cap, lowered to the descriptors').
  int max_connections() const;
  HttpEngineCounts counts() const;
  // Each open event stream sends what was published since its cursor.
  void wake_event_streams();
  // Room may have come (a file copy of the reply budget freed, or one made that a waiting request
  // may share): the first request waiting for room runs its route again, and the next once it is
  // served (in the order they came, stopping at the first that finds none). From any thread;
  // nothing once stopped.
  void retry_room_waiters();
  // Closes the listening socket, the idle connections and the event streams; the routes under way
  // run to their end and their replies are sent (within limits.stop_grace_deadline, then every
  // connection is closed); joins. Idempotent.
  void stop();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace vimg::web
