#pragma once
// The sending side of one open event stream (web/server/event_stream.hpp) in a connection
// (web/server/http_connection.hpp, network thread only): its cursor in the broadcaster, the chunks
// waiting to be written, a keep-alive comment every kEventKeepAlive (so a page that has gone is
// noticed), and its end: when the broadcaster closes or the stream's lifetime is over, the last
// chunk is queued and the connection closes once it is written. The page's EventSource then opens
// another after the stream's retry hint, with the Last-Event-ID of the last message it got.
#include <boost/asio/io_context.hpp>
#include <boost/asio/steady_timer.hpp>
#include <chrono>
#include <cstdint>
#include <functional>
#include <string>

#include "web/server/event_stream.hpp"
#include "web/server/http_message.hpp"

namespace vimg::web {

class EventStreamWriter {
 public:
  explicit EventStreamWriter(boost::asio::io_context& io) : keep_alive_(io), lifetime_(io) {}

  // The reply that opened the stream is being written; the stream holds a place from now on.
  void opened(std::int64_t cursor) {
    holds_place_ = true;
    cursor_ = cursor;
  }
  bool open() const { return holds_place_; }
  // The greeting is written and the stream armed: chunks may be written now (not while the
  // reply's head is still being written).
  bool streaming() const { return holds_place_ && flush_ != nullptr; }
  bool ended() const { return ending_; }

  // Starts the keep-alive comments and the lifetime; `flush` writes what take() gives.
  void arm(std::chrono::milliseconds lifetime, std::function<void()> flush) {
    flush_ = std::move(flush);
    arm_keep_alive();
    lifetime_.expires_after(lifetime);
    lifetime_.async_wait([this](const boost::system::error_code& ec) {
      if (ec || !holds_place_) return;
      end();
      call_flush();
    });
  }

  // What was published after the cursor (the last chunk once the broadcaster closed).
  void changed(EventBroadcaster& events) {
    const EventBroadcaster::Wait wait = events.wait_after(cursor_, std::chrono::milliseconds(0));
    if (wait.closed) {
      end();
    } else if (!wait.text.empty() && !ending_) {
      outbox_ += format_chunk(wait.text);
    }
  }

  std::string take() {
    std::string out = std::move(outbox_);
    outbox_.clear();
    return out;
  }

  // The connection closes: the timers stop and the place is given back.
  void close(EventBroadcaster* events) {
    keep_alive_.cancel();
    lifetime_.cancel();
    flush_ = nullptr;
    if (holds_place_ && events) events->close_stream();
    holds_place_ = false;
  }

 private:
  void end() {
    if (ending_) return;
    outbox_ += format_chunk("");
    ending_ = true;
  }

  // A copy is called: the flush may close the connection, and close() drops flush_.
  void call_flush() {
    const std::function<void()> flush = flush_;
    if (flush) flush();
  }

  void arm_keep_alive() {
    keep_alive_.expires_after(kEventKeepAlive);
    keep_alive_.async_wait([this](const boost::system::error_code& ec) {
      if (ec || !holds_place_) return;
      if (outbox_.empty() && !ending_) outbox_ = format_chunk(": keep-alive\n\n");
      arm_keep_alive();
      call_flush();
    });
  }

  boost::asio::steady_timer keep_alive_, lifetime_;
  std::function<void()> flush_;
  std::int64_t cursor_ = 0;
  std::string outbox_;
  bool holds_place_ = false, ending_ = false;
};

}  // namespace vimg::web
