#pragma once
// One connection of the HTTP engine (web/server/http_engine.hpp), over plain TCP or TLS: included by
// http_engine.cpp only (Beast's templates are compiled there and nowhere else). Everything here runs
// on the network thread, except respond(), which a worker runs and whose reply is posted back.
//   connect -> [TLS handshake] -> header (kHeaderDeadline) -> refuse? -> body (kBodyDeadline)
//   -> respond on a worker -> reply -> keep-alive: header again | close | event stream
#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/post.hpp>
#include <boost/asio/ssl.hpp>
#include <boost/asio/steady_timer.hpp>
#include <boost/asio/thread_pool.hpp>
#include <boost/asio/write.hpp>
#include <boost/beast/core/flat_buffer.hpp>
#include <boost/beast/core/string.hpp>
#include <boost/beast/core/tcp_stream.hpp>
#include <boost/beast/http/error.hpp>
#include <boost/beast/http/parser.hpp>
#include <boost/beast/http/read.hpp>
#include <boost/beast/http/string_body.hpp>
#include <array>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <type_traits>
#include <unordered_map>

#include "web/server/http_engine.hpp"

namespace vimg::web {

namespace net = boost::asio;
namespace beast = boost::beast;
namespace http = beast::http;
using tcp = net::ip::tcp;
using TlsStream = net::ssl::stream<beast::tcp_stream>;

// Room for the whole header, the largest body and a pipelined request's start.
inline constexpr std::size_t kMaxBufferedBytes = 32768;

class Connection {
 public:
  virtual ~Connection() = default;
  virtual void start() = 0;
  virtual void abort() = 0;           // closes the socket now
  virtual void events_changed() = 0;  // an event stream sends what is new
};

// What every connection shares; touched on the network thread only (the pool is thread-safe).
struct EngineState {
  HttpRoutes routes;
  net::io_context io{1};
  std::optional<net::thread_pool> pool;
  std::unordered_map<Connection*, std::weak_ptr<Connection>> open;
  int max_connections = kMaxConnections;
  bool stopping = false;
};

template <class Stream>
class Session final : public Connection, public std::enable_shared_from_this<Session<Stream>> {
  static constexpr bool kTls = std::is_same_v<Stream, TlsStream>;

 public:
  Session(EngineState& engine, Stream stream) : engine_(engine), stream_(std::move(stream)), keep_alive_timer_(engine.io) {}

  void start() override {
    if constexpr (kTls) {
      tcp_layer().expires_after(kTlsHandshakeDeadline);
      stream_.async_handshake(net::ssl::stream_base::server, [self = this->shared_from_this()](beast::error_code ec) {
        if (ec) return self->finish();
        self->read_header();
      });
    } else {
      read_header();
    }
  }

  void abort() override { finish(); }

  void events_changed() override {
    if (!stream_open_ || finished_) return;
    const EventBroadcaster::Wait wait = engine_.routes.events->wait_after(cursor_, std::chrono::milliseconds(0));
    if (wait.closed) {
      outbox_ += format_chunk("");
      ending_ = true;
    } else if (!wait.text.empty()) {
      outbox_ += format_chunk(wait.text);
    }
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
    tcp_layer().expires_after(kHeaderDeadline);
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
    request_.host = std::string(head[http::field::host]);
    request_.origin = std::string(head[http::field::origin]);
    request_.key = std::string(head["X-Vimg-Key"]);
    request_.content_type = std::string(head[http::field::content_type]);
    if (auto refusal = engine_.routes.refuse(request_)) return send(std::move(*refusal), true);
    parser_->body_limit(engine_.routes.max_body_bytes);
    if (parser_->content_length() && *parser_->content_length() > engine_.routes.max_body_bytes) {
      return send(text_reply(413, "payload too large"), true);
    }
    if (parser_->is_done()) return dispatch();
    if (beast::iequals(head[http::field::expect], "100-continue")) {
      continue_ = "HTTP/1.1 100 Continue\r\n\r\n";
      tcp_layer().expires_after(kBodyDeadline);
      return net::async_write(stream_, net::buffer(continue_), [self = this->shared_from_this()](beast::error_code e, std::size_t) {
        if (e) return self->finish();
        self->read_body();
      });
    }
    tcp_layer().expires_after(kBodyDeadline);
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

  // The route runs on a worker; the reply comes back to this thread.
  void dispatch() {
    tcp_layer().expires_never();
    net::post(*engine_.pool, [self = this->shared_from_this()]() mutable {
      HttpReply reply = self->engine_.routes.respond(self->request_);
      EngineState& engine = self->engine_;
      net::post(engine.io, [self = std::move(self), reply = std::move(reply)]() mutable {
        self->send(std::move(reply), false);
      });
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
    holds_stream_ = reply.event_stream;
    cursor_ = reply.stream_cursor;
    head_ = format_reply_head(reply, reply.body.size());
    if (reply.event_stream) {
      head_ += format_chunk(reply.body);
      body_.clear();
    } else {
      body_ = request_.method == "HEAD" ? std::string() : std::move(reply.body);
    }
    tcp_layer().expires_after(write_deadline(head_.size() + body_.size()));
    const std::array<net::const_buffer, 2> buffers{net::buffer(head_), net::buffer(body_)};
    net::async_write(stream_, buffers,
                     [self = this->shared_from_this(), close = reply.close, stream = reply.event_stream](beast::error_code ec, std::size_t) {
                       if (ec || self->finished_) return self->finish();
                       if (stream) return self->open_stream();
                       if (close) return self->close_gracefully();
                       self->read_header();
                     });
  }

  void open_stream() {
    head_.clear();
    stream_open_ = true;
    // A page that closes its stream is noticed at once (its slot of kMaxEventStreams freed), not at
    // the next keep-alive comment: a read stays pending, untimed (a write's deadline is its own).
    tcp_layer().expires_never();
    stream_.async_read_some(net::buffer(scratch_), [self = this->shared_from_this()](beast::error_code, std::size_t) {
      self->finish();
    });
    arm_keep_alive();
    events_changed();  // what was published while the greeting was written
  }

  void arm_keep_alive() {
    keep_alive_timer_.expires_after(kEventKeepAlive);
    keep_alive_timer_.async_wait([self = this->shared_from_this()](beast::error_code ec) {
      if (ec || self->finished_) return;
      if (!self->writing_ && self->outbox_.empty()) self->outbox_ = format_chunk(": keep-alive\n\n");
      self->flush_stream();
      self->arm_keep_alive();
    });
  }

  void flush_stream() {
    if (writing_ || finished_) return;
    if (outbox_.empty()) {
      if (ending_) finish();  // the last chunk is out (the read pending rules out a graceful drain)
      return;
    }
    writing_ = true;
    sending_ = std::move(outbox_);
    outbox_.clear();
    tcp_layer().expires_after(kWriteDeadline);
    net::async_write(stream_, net::buffer(sending_), [self = this->shared_from_this()](beast::error_code ec, std::size_t) {
      self->writing_ = false;
      if (ec) return self->finish();
      self->flush_stream();
    });
  }

  // The reply is out; the peer's last bytes are read (closing with them unread would reset the
  // connection and could lose the reply), for kClosingDeadline at most.
  void close_gracefully() {
    if (finished_) return;
    tcp_layer().expires_after(kClosingDeadline);
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
    stream_open_ = false;
    keep_alive_timer_.cancel();
    tcp_layer().close();
    if (holds_stream_) engine_.routes.events->close_stream();
    holds_stream_ = false;
    engine_.open.erase(this);
  }

  EngineState& engine_;
  Stream stream_;
  beast::flat_buffer buffer_{kMaxBufferedBytes};
  std::optional<http::request_parser<http::string_body>> parser_;
  HttpRequest request_;
  std::string head_, body_, continue_;
  std::array<char, 512> scratch_{};
  // An event stream: its cursor, what waits to be sent, what is being sent.
  net::steady_timer keep_alive_timer_;
  std::int64_t cursor_ = 0;
  std::string outbox_, sending_;
  bool holds_stream_ = false, stream_open_ = false, writing_ = false, ending_ = false;
  bool finished_ = false;
};

}  // namespace vimg::web
