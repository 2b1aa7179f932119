#pragma once
// One connection of the HTTP engine (web/server/http_engine.hpp), over plain TCP or TLS: included by
// http_engine.cpp only (Beast's templates are compiled there and nowhere else). Everything here runs
// on the network thread, except the route, which a worker runs and whose reply is posted back.
//   connect -> [TLS handshake] -> header (header deadline) -> refuse? -> body (body deadline)
//   -> screen? -> route on a worker (dropped if the client goes meanwhile)
//   [-> no room: wait for room (reply budget wait) -> route again] -> reply (write deadline)
//   -> keep-alive: header again | close | event stream (until its lifetime ends)
#include <sys/socket.h>

#include <boost/asio/post.hpp>
#include <boost/asio/write.hpp>
#include <boost/beast/core/flat_buffer.hpp>
#include <boost/beast/core/string.hpp>
#include <boost/beast/http/error.hpp>
#include <boost/beast/http/parser.hpp>
#include <boost/beast/http/read.hpp>
#include <boost/beast/http/string_body.hpp>
#include <array>
#include <cerrno>
#include <chrono>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <type_traits>

#include "web/server/engine_state.hpp"
#include "web/server/event_stream_writer.hpp"

namespace vimg::web {

namespace http = beast::http;
using TlsStream = net::ssl::stream<beast::tcp_stream>;

inline constexpr std::size_t kMaxBufferedBytes = 32768;  // the whole header, the largest body, a pipelined start

// The request's framing is one the server will read: a single Content-Length, or chunked alone. Anything
// else (both, a length twice, a list, another coding) a proxy in front could read differently: 400.
inline bool unambiguous_framing(const http::request_parser<http::string_body>::value_type& head) {
  const auto lengths = head.count(http::field::content_length);
  const auto codings = head.count(http::field::transfer_encoding);
  if (lengths > 1 || codings > 1 || (lengths == 1 && codings == 1)) return false;
  if (lengths == 1 && head[http::field::content_length].find(',') != beast::string_view::npos) return false;
  return codings == 0 || beast::iequals(head[http::field::transfer_encoding], "chunked");
}

template <class Stream>
class Session final : public Connection, public std::enable_shared_from_this<Session<Stream>> {
  static constexpr bool kTls = std::is_same_v<Stream, TlsStream>;

 public:
  Session(EngineState& engine, Stream stream)
      : engine_(engine), stream_(std::move(stream)), events_(engine.io), room_timer_(engine.io) {}

  void start() override {
    if constexpr (kTls) {
      tcp_layer().expires_after(engine_.limits().tls_handshake_deadline);
      stream_.async_handshake(net::ssl::stream_base::server, [self = this->shared_from_this()](beast::error_code ec) {
        if (ec) return self->finish();
        self->read_header();
      });
    } else {
      read_header();
    }
  }

  void abort() override { finish(); }

  void stop_gracefully() override {
    if (waiting_for_room_) {  // its 503 now
      stop_waiting_for_room();
      return route_done(std::move(waiting_reply_));
    }
    if (in_flight_) return;  // send() closes after the reply (the engine is stopping)
    finish();
  }

  bool retry_for_room() override {
    if (!waiting_for_room_ || finished_) return false;
    stop_waiting_for_room();
    queue_route();
    return true;
  }

  void events_changed() override {
    if (finished_ || !events_.streaming()) return;
    events_.changed(*engine_.routes.events);
    flush_stream();
  }

 private:
  beast::tcp_stream& tcp_layer() { return beast::get_lowest_layer(stream_); }

  std::string_view buffered() const {
    return {static_cast<const char*>(buffer_.data().data()), buffer_.size()};
  }

  void read_header() {
    if (finished_) return;
    parser_.emplace();
    parser_->header_limit(kMaxHeaderBytes);
    // The route refuses first; the body's bound follows. (Beast 1.74 compares a length with an
    // empty limit as greater, so "no limit" is the largest one.)
    parser_->body_limit(std::numeric_limits<std::uint64_t>::max());
    request_ = HttpRequest{};
    room_deadline_.reset();
    room_ticket_.reset();
    // One deadline for the whole header, however its bytes trickle (not one per read).
    tcp_layer().expires_after(engine_.limits().header_deadline);
    http::async_read_header(stream_, buffer_, *parser_, [self = this->shared_from_this()](beast::error_code ec, std::size_t) {
      self->on_header(ec);
    });
  }

  void on_header(beast::error_code ec) {
    if (finished_) return;
    if (ec) {
      if (ec == http::error::header_limit || ec == http::error::buffer_overflow) {
        // The parser has taken the request line off the buffer once it was complete.
        const std::size_t target_bytes = parser_->get().target().size();
        const int status = target_bytes > 0 ? (target_bytes > kMaxRequestLineBytes ? 414 : 400)
                                             : oversized_header_status(buffered());
        return send(text_reply(status, "request header too large"), true);
      }
      const bool malformed = ec.category() == http::make_error_code(http::error::bad_target).category() &&
                             ec != http::error::end_of_stream && ec != http::error::partial_message;
      if (malformed) return send(text_reply(400, "bad request: " + ec.message()), true);
      return finish();  // closed, timed out, reset: nothing to answer
    }
    const auto& head = parser_->get();
    request_.method = std::string(head.method_string());
    request_.target = std::string(head.target());
    split_target(request_.target, request_);
    if (request_.target.size() > kMaxRequestLineBytes) return send(text_reply(414, "request line too long"), true);
    for (const auto& field : head) {
      if (field.name_string().size() + 2 + field.value().size() > kMaxHeaderLineBytes) {
        return send(text_reply(400, "header line too long"), true);
      }
    }
    if (!unambiguous_framing(head)) {
      return send(text_reply(400, "bad request: one Content-Length, or Transfer-Encoding: chunked alone"), true);
    }
    request_.host = std::string(head[http::field::host]);
    request_.origin = std::string(head[http::field::origin]);
    for (const std::string& name : engine_.routes.passed_fields) request_.passed_fields.emplace_back(name, head[name]);
    client_ = engine_.routes.client_field.empty() ? std::string() : std::string(head[engine_.routes.client_field]);
    request_.content_type = std::string(head[http::field::content_type]);
    request_.last_event_id = std::string(head["Last-Event-ID"]);
    if (auto refusal = engine_.routes.refuse(request_)) return send(std::move(*refusal), true);
    parser_->body_limit(engine_.routes.max_body_bytes);
    if (parser_->content_length() && *parser_->content_length() > engine_.routes.max_body_bytes) {
      return send(text_reply(413, "payload too large"), true);
    }
    if (parser_->is_done()) return dispatch();
    tcp_layer().expires_after(engine_.limits().body_deadline);
    if (beast::iequals(head[http::field::expect], "100-continue")) {
      continue_ = "HTTP/1.1 100 Continue\r\n\r\n";
      return net::async_write(stream_, net::buffer(continue_), [self = this->shared_from_this()](beast::error_code e, std::size_t) {
        if (e) return self->finish();
        self->read_body();
      });
    }
    read_body();
  }

  void read_body() {
    if (finished_) return;
    http::async_read(stream_, buffer_, *parser_, [self = this->shared_from_this()](beast::error_code ec, std::size_t) {
      if (self->finished_) return;
      if (ec == http::error::body_limit) return self->send(text_reply(413, "payload too large"), true);
      if (ec) return self->finish();
      self->request_.body = std::move(self->parser_->get().body());
      self->dispatch();
    });
  }

  // Refused at once by the screen, or the route runs on a worker of its queue and the reply comes back
  // here; meanwhile a client that closes (or half-closes) is dropped and its route not run.
  void dispatch() {
    tcp_layer().expires_never();
    if (engine_.routes.screen) {
      std::string failure;
      auto refusal = run_route(engine_.routes.screen, request_, failure);
      log_failure(failure);
      if (refusal) {
        ++engine_.counts.refused_early;
        return send(std::move(*refusal), false);
      }
    }
    in_flight_ = true;
    watch_for_departure();
    queue_route();
  }

  void queue_route() {
    const int pool = request_.method == "POST" ? 1 : 0;
    // Run again for room (a file's, no lock), it skips its client's turn: never held behind another.
    std::string queue = room_deadline_ ? std::string() : client_;
    queued_generation_ = engine_.room_generation;
    ++engine_.counts.routes_queued;
    engine_.run_route_job(pool, queue, [self = this->shared_from_this(), pool, queue]() mutable {
      HttpReply reply;
      std::string failure;
      if (self->departed_.load()) {
        ++self->engine_.counts.routes_dropped;
      } else {
        reply = run_route(self->engine_.routes.respond, self->request_, failure);
      }
      EngineState& engine = self->engine_;
      net::post(engine.io, [self = std::move(self), reply = std::move(reply), failure = std::move(failure), pool, queue]() mutable {
        self->engine_.route_job_done(pool, queue);
        self->log_failure(failure);
        self->route_done(std::move(reply));
      });
    });
  }

  void log_failure(const std::string& failure) {
    if (failure.empty()) return;
    ++engine_.counts.routes_failed;
    if (engine_.routes.log_failure) engine_.routes.log_failure(request_, failure);
  }

  // The route's reply: sent, or (no room yet) it waits in its place, in turn to run again when the
  // copies change (EngineState::retry_next_room_waiter), until the reply budget wait has passed.
  void route_done(HttpReply reply) {
    if (reply.wait_for_room && !finished_ && !engine_.stopping) {
      const auto now = std::chrono::steady_clock::now();
      if (!room_deadline_) room_deadline_ = now + engine_.limits().reply_budget_wait;
      if (now < *room_deadline_) {
        if (engine_.room_generation != queued_generation_) return queue_route();  // changed meanwhile
        engine_.room_retry_ended(this, false);  // still no room: the others wait for the next change
        return wait_for_room(std::move(reply));
      }
      ++engine_.counts.room_waits_expired;
    }
    engine_.room_retry_ended(this, true);  // served, or its wait is over: the next may fit
    in_flight_ = false;
    beast::error_code ignored;
    tcp_layer().socket().cancel(ignored);  // the watch
    send(std::move(reply), false);
  }

  // On the network thread, with no worker and no reply bytes: the reply kept is the route's 503.
  void wait_for_room(HttpReply reply) {
    waiting_reply_ = std::move(reply);
    waiting_for_room_ = true;
    ++engine_.counts.waiting_for_room;
    if (!room_ticket_) room_ticket_ = engine_.next_room_ticket++;  // its place, kept while it waits again
    engine_.room_waiters.emplace(*room_ticket_, this->weak_from_this());
    room_timer_.expires_at(*room_deadline_);
    room_timer_.async_wait([self = this->shared_from_this()](beast::error_code ec) {
      if (ec || !self->waiting_for_room_) return;
      self->stop_waiting_for_room();
      self->route_done(std::move(self->waiting_reply_));  // past the deadline: the 503
      self->engine_.retry_next_room_waiter();  // the next in turn, which may fit where this did not
    });
  }

  void stop_waiting_for_room() {
    if (!waiting_for_room_) return;
    waiting_for_room_ = false;
    --engine_.counts.waiting_for_room;
    engine_.room_waiters.erase(*room_ticket_);
    room_timer_.cancel();
  }

  // Readable while the route runs: the peer's FIN (recv peeks 0) or an error means it has gone; a
  // pipelined request's bytes stay where they are for the next read.
  void watch_for_departure() {
    tcp_layer().socket().async_wait(tcp::socket::wait_read, [self = this->shared_from_this()](beast::error_code ec) {
      if (ec || self->finished_ || !self->in_flight_) return;
      char byte = 0;
      const ssize_t n = ::recv(self->tcp_layer().socket().native_handle(), &byte, 1, MSG_PEEK | MSG_DONTWAIT);
      if (n > 0) return;
      if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR)) return self->watch_for_departure();
      self->departed_ = true;
      self->finish();
    });
  }

  void send(HttpReply reply, bool refused) {
    if (finished_) {
      if (reply.event_stream) engine_.routes.events->close_stream();
      return;
    }
    if (refused || !parser_ || !parser_->is_header_done() || !parser_->get().keep_alive() || engine_.stopping) {
      reply.close = true;
    }
    engine_.routes.log(request_, reply);
    const bool head_only = request_.method == "HEAD" || reply.head_only_bytes.has_value();
    head_ = format_reply_head(reply, reply.content_length());
    if (reply.event_stream) {
      head_ += format_chunk(reply.body);
      events_.opened(reply.stream_cursor);
      reply_ = HttpReply{};
    } else {
      reply_ = std::move(reply);  // holds the body (or the file's shared copy) until written
      if (head_only) {
        reply_.body.clear();
        reply_.shared_body.reset();
      }
    }
    const std::string_view body = reply_.body_bytes();
    tcp_layer().expires_after(write_deadline(engine_.limits(), head_.size() + body.size()));
    const std::array<net::const_buffer, 2> buffers{net::buffer(head_), net::buffer(body.data(), body.size())};
    net::async_write(stream_, buffers, [self = this->shared_from_this()](beast::error_code ec, std::size_t) {
      self->reply_.shared_body.reset();  // the file's copy leaves the reply budget once written
      self->reply_.body.clear();
      if (ec || self->finished_) return self->finish();
      if (self->events_.open()) return self->open_stream();
      if (self->reply_.close) return self->close_gracefully();
      self->read_header();
    });
  }

  void open_stream() {
    head_.clear();
    // A page that closes its stream is noticed at once (its place among kMaxEventStreams freed),
    // not at the next keep-alive comment: a read stays pending, untimed (a write's deadline is its own).
    tcp_layer().expires_never();
    stream_.async_read_some(net::buffer(scratch_), [self = this->shared_from_this()](beast::error_code, std::size_t) {
      self->finish();
    });
    events_.arm(engine_.limits().event_stream_lifetime, [self = this->shared_from_this()] { self->flush_stream(); });
    events_changed();  // what was published while the greeting was written
  }

  void flush_stream() {
    if (writing_ || finished_) return;
    std::string next = events_.take();
    if (next.empty()) {
      if (events_.ended()) finish();  // the last chunk is out (the read pending rules out a graceful drain)
      return;
    }
    writing_ = true;
    sending_ = std::move(next);
    tcp_layer().expires_after(engine_.limits().write_deadline);
    net::async_write(stream_, net::buffer(sending_), [self = this->shared_from_this()](beast::error_code ec, std::size_t) {
      self->writing_ = false;
      if (ec) return self->finish();
      self->flush_stream();
    });
  }

  // The reply is out; the peer's last bytes are read (closing with them unread would reset the
  // connection and could lose the reply), for the closing deadline at most.
  void close_gracefully() {
    if (finished_) return;
    tcp_layer().expires_after(engine_.limits().closing_deadline);
    if constexpr (kTls) {
      stream_.async_shutdown([self = this->shared_from_this()](beast::error_code) { self->finish(); });
    } else {
      beast::error_code ec;
      tcp_layer().socket().shutdown(tcp::socket::shutdown_send, ec);
      drain();
    }
  }

  void drain() {
    tcp_layer().async_read_some(net::buffer(scratch_), [self = this->shared_from_this()](beast::error_code ec, std::size_t) {
      if (ec || self->finished_) return self->finish();
      self->drain();
    });
  }

  void finish() {
    if (finished_) return;
    finished_ = true;
    stop_waiting_for_room();
    engine_.room_retry_ended(this, true);
    tcp_layer().close();
    events_.close(engine_.routes.events);
    reply_.shared_body.reset();
    engine_.closed(this, false);
  }

  EngineState& engine_;
  Stream stream_;
  beast::flat_buffer buffer_{kMaxBufferedBytes};
  std::optional<http::request_parser<http::string_body>> parser_;
  HttpRequest request_;
  std::string client_;  // the request's value of HttpRoutes::client_field: its routes run one at a time
  HttpReply reply_;  // being written
  std::string head_, continue_, sending_;
  std::array<char, 512> scratch_{};
  EventStreamWriter events_;
  net::steady_timer room_timer_;  // the end of the wait for room
  std::optional<std::chrono::steady_clock::time_point> room_deadline_;  // set when the request first waits
  std::optional<std::uint64_t> room_ticket_;  // its place among those waiting (EngineState::room_waiters)
  HttpReply waiting_reply_;  // while waiting for room: the route's 503, sent at the deadline
  std::uint64_t queued_generation_ = 0;  // EngineState::room_generation when the route was queued
  bool waiting_for_room_ = false;
  std::atomic<bool> departed_{false};  // set here, read by the worker about to run the route
  bool in_flight_ = false, writing_ = false, finished_ = false;
};

}  // namespace vimg::web
