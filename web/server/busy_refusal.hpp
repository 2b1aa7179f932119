#pragma once
// A connection beyond the cap (web/server/descriptor_budget.hpp), over plain TCP: its request head
// is read first (up to kMaxHeaderBytes, for the closing deadline at most), then 503 is written, the
// sending side shut and what the client still sends read until it closes (closing deadline). A 503
// written to a socket closed with the request unread can be lost to the reset the kernel sends
// for unread bytes; this way it is delivered. Over TLS the connection is closed at once (a
// handshake for a refusal is not spent). Included by http_engine.cpp only.
#include <boost/asio/write.hpp>
#include <boost/beast/core/error.hpp>
#include <array>
#include <string>

#include "web/server/engine_state.hpp"

namespace vimg::web {

class BusyRefusal final : public Connection, public std::enable_shared_from_this<BusyRefusal> {
 public:
  BusyRefusal(EngineState& engine, tcp::socket socket) : engine_(engine), stream_(std::move(socket)) {}

  void start() override {
    stream_.expires_after(engine_.limits().closing_deadline);
    read_head();
  }

  void abort() override { finish(); }

  static const std::string& reply() {
    static const std::string kBusy = [] {
      HttpReply busy = text_reply(503, "the server is busy (too many connections); try again");
      busy.headers.emplace_back("Retry-After", "1");
      busy.close = true;
      return format_reply_head(busy, busy.body.size()) + busy.body;
    }();
    return kBusy;
  }

 private:
  void read_head() {
    stream_.async_read_some(net::buffer(scratch_), [self = shared_from_this()](beast::error_code ec, std::size_t n) {
      if (self->finished_) return;
      if (ec && ec != beast::error::timeout) return self->finish();  // gone: nobody to answer
      self->head_.append(self->scratch_.data(), n);
      if (!ec && self->head_.find("\r\n\r\n") == std::string::npos && self->head_.size() < kMaxHeaderBytes) {
        return self->read_head();
      }
      self->answer();
    });
  }

  void answer() {
    head_.clear();
    stream_.expires_after(write_deadline(engine_.limits(), reply().size()));
    net::async_write(stream_, net::buffer(reply()), [self = shared_from_this()](beast::error_code ec, std::size_t) {
      if (ec || self->finished_) return self->finish();
      beast::error_code ignored;
      self->stream_.socket().shutdown(tcp::socket::shutdown_send, ignored);
      self->stream_.expires_after(self->engine_.limits().closing_deadline);
      self->drain();
    });
  }

  void drain() {
    stream_.async_read_some(net::buffer(scratch_), [self = shared_from_this()](beast::error_code ec, std::size_t) {
      if (ec || self->finished_) return self->finish();
      self->drain();
    });
  }

  void finish() {
    if (finished_) return;
    finished_ = true;
    stream_.close();
    engine_.closed(this, true);
  }

  EngineState& engine_;
  beast::tcp_stream stream_;
  std::string head_;
  std::array<char, 2048> scratch_{};
  bool finished_ = false;
};

}  // namespace vimg::web
