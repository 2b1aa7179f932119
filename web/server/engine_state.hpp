#pragma once
// What every connection of the HTTP engine (web/server/http_engine.hpp) shares: included by
// http_engine.cpp only, with the connection (web/server/http_connection.hpp) and the refusal at the
// cap (web/server/busy_refusal.hpp). Touched on the network thread only, except the counts
// (atomic) and the pools (thread-safe).
#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/ssl.hpp>
#include <boost/asio/steady_timer.hpp>
#include <boost/asio/thread_pool.hpp>
#include <boost/beast/core/tcp_stream.hpp>
#include <atomic>
#include <memory>
#include <optional>
#include <unordered_map>

#include "web/server/http_engine.hpp"

namespace vimg::web {

namespace net = boost::asio;
namespace beast = boost::beast;
using tcp = net::ip::tcp;

class Connection {
 public:
  virtual ~Connection() = default;
  virtual void start() = 0;
  virtual void abort() = 0;           // closes the socket now
  virtual void events_changed() {}    // an event stream sends what is new
  // The server stops: a connection whose route is under way sends its reply and then closes;
  // any other closes now.
  virtual void stop_gracefully() { abort(); }
};

struct AtomicCounts {
  std::atomic<int> open_connections{0};
  std::atomic<long> refused_busy{0}, closed_unanswered{0}, routes_queued{0}, routes_dropped{0}, routes_failed{0};
};

struct EngineState {
  HttpRoutes routes;
  net::io_context io{1};
  std::optional<net::thread_pool> read_pool, write_pool;
  std::unordered_map<Connection*, std::weak_ptr<Connection>> open;  // served and refused alike
  int connections = 0, refusing = 0;  // of `open`: served, being answered 503
  int descriptor_limit = 0;
  bool stopping = false;
  std::optional<net::steady_timer> stop_deadline;  // while stopping: closes what is left
  AtomicCounts counts;

  const HttpLimits& limits() const { return routes.limits; }

  // A connection has closed (each calls this once).
  void closed(Connection* connection, bool refusal) {
    if (open.erase(connection) == 0) return;
    if (refusal) {
      --refusing;
    } else {
      --connections;
      counts.open_connections = connections;
    }
    if (stopping && open.empty() && stop_deadline) stop_deadline->cancel();
  }
};

}  // namespace vimg::web
