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
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <exception>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <string>
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
  // A request waiting for room runs its route again: false when it no longer waits.
  virtual bool retry_for_room() { return false; }
  // The server stops: a connection whose route is under way sends its reply and then closes;
  // any other closes now.
  virtual void stop_gracefully() { abort(); }
};

struct AtomicCounts {
  std::atomic<int> open_connections{0};
  std::atomic<long> refused_busy{0}, closed_unanswered{0}, routes_queued{0}, routes_dropped{0}, routes_failed{0};
  std::atomic<long> refused_early{0}, room_waits_expired{0};
  std::atomic<int> waiting_for_room{0};
};

// A route (respond on a worker, screen on the network thread): its result, or 500 when it throws
// (`failure` then says what).
template <class Result>
Result run_route(const std::function<Result(const HttpRequest&)>& route, const HttpRequest& request, std::string& failure) {
  try {
    return route(request);
  } catch (const std::exception& e) {
    failure = e.what();
  } catch (...) {
    failure = "an exception that is not a std::exception";
  }
  return text_reply(500, "the server could not answer this request (its log says why)");
}

// The routes of one client (one value of HttpRoutes::client_field) on one pool: one runs at a
// time, the others wait here, on the network thread, costing no worker.
struct ClientQueue {
  bool running = false;
  std::deque<std::function<void()>> waiting;
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
  std::unordered_map<std::string, ClientQueue> client_queues[2];  // [0]: reading pool, [1]: writing pool
  // The requests waiting for room in the reply budget, by the order in which they first found none
  // (each takes itself out when it stops waiting, and goes back to its place when it still finds
  // none); the one of them whose route runs again now, if any (one at a time); and how many times
  // the copies changed: a route that found no room and comes back after a change it did not see is
  // run again at once instead of waiting.
  std::map<std::uint64_t, std::weak_ptr<Connection>> room_waiters;
  std::uint64_t next_room_ticket = 0;
  Connection* room_retrying = nullptr;
  std::uint64_t room_generation = 0;
  // Routes handed to a pool (or waiting for their client's turn) whose reply has not come back;
  // stop() waits for none to be left before it joins the pools.
  std::mutex pending_mutex;
  std::condition_variable pending_changed;
  int routes_pending = 0;

  net::thread_pool& pool(int index) { return index == 0 ? *read_pool : *write_pool; }

  // Runs `job` on the pool now, or after the client's route under way there.
  void run_route_job(int pool_index, const std::string& client, std::function<void()> job) {
    {
      const std::lock_guard lock(pending_mutex);
      ++routes_pending;
    }
    if (client.empty()) return net::post(pool(pool_index), std::move(job));
    ClientQueue& queue = client_queues[pool_index][client];
    if (!queue.running) {
      queue.running = true;
      return net::post(pool(pool_index), std::move(job));
    }
    queue.waiting.push_back(std::move(job));
  }

  // A route's reply is back on the network thread: the client's next route goes to the pool.
  void route_job_done(int pool_index, const std::string& client) {
    if (!client.empty()) {
      const auto found = client_queues[pool_index].find(client);
      if (found != client_queues[pool_index].end()) {
        if (found->second.waiting.empty()) {
          client_queues[pool_index].erase(found);
        } else {
          net::post(pool(pool_index), std::move(found->second.waiting.front()));
          found->second.waiting.pop_front();
        }
      }
    }
    const std::lock_guard lock(pending_mutex);
    if (--routes_pending == 0) pending_changed.notify_all();
  }

  const HttpLimits& limits() const { return routes.limits; }

  // The copies changed (one freed, or one made): the first request waiting for room runs its route
  // again, unless one does already (it then runs again itself, having missed this change).
  void wake_room_waiters() {
    ++room_generation;
    retry_next_room_waiter();
  }

  // The first request waiting for room runs its route again, if none does now. Called again when
  // that one is served or leaves, so that the next follows; when it still finds no room it goes
  // back to its place and the others wait for the next change (in order: stopped at the first
  // that does not fit).
  void retry_next_room_waiter() {
    while (room_retrying == nullptr && !stopping && !room_waiters.empty()) {
      const auto [ticket, weak] = *room_waiters.begin();
      const std::shared_ptr<Connection> first = weak.lock();
      room_retrying = first.get();
      if (!first || !first->retry_for_room()) {  // gone, or no longer waiting: not a waiter
        room_retrying = nullptr;
        room_waiters.erase(ticket);
      }
    }
  }

  // `connection`'s retry has ended (it was served, refused, closed, or waits again): the next may run.
  void room_retry_ended(Connection* connection, bool next) {
    if (room_retrying != connection) return;
    room_retrying = nullptr;
    if (next) retry_next_room_waiter();
  }

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
