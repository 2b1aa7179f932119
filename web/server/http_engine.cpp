#include "web/server/http_engine.hpp"

#include <boost/asio/executor_work_guard.hpp>
#include <boost/asio/post.hpp>
#include <boost/beast/core/error.hpp>
#include <cstdio>
#include <exception>
#include <future>
#include <thread>
#include <vector>

#include "web/server/busy_refusal.hpp"
#include "web/server/descriptor_budget.hpp"
#include "web/server/http_connection.hpp"

namespace vimg::web {

struct HttpEngine::Impl {
  explicit Impl(HttpRoutes routes) { state.routes = std::move(routes); }
  EngineState state;
  std::optional<net::ssl::context> tls;
  std::optional<tcp::acceptor> acceptor;
  std::optional<net::steady_timer> retry_accept;
  std::optional<net::executor_work_guard<net::io_context::executor_type>> work;
  std::thread network;
  int port = 0;
  std::atomic<bool> running{false};  // read by wake_event_streams() from any thread

  void accept() {
    acceptor->async_accept(state.io, [this](beast::error_code ec, tcp::socket socket) {
      if (state.stopping || ec == net::error::operation_aborted) return;
      if (ec) {  // out of descriptors or memory: try again shortly, never in a busy loop
        retry_accept->expires_after(std::chrono::milliseconds(50));
        retry_accept->async_wait([this](beast::error_code wait_ec) {
          if (!wait_ec && !state.stopping) accept();
        });
        return;
      }
      admit(std::move(socket));
      accept();
    });
  }

  void admit(tcp::socket socket) {
    const DescriptorUse use{state.connections, state.refusing, state.routes.files_held ? state.routes.files_held() : 0};
    Admission admission = admit_connection(use, state.limits().max_connections, state.descriptor_limit);
    if (admission == Admission::refuse_busy && tls) admission = Admission::close;
    std::shared_ptr<Connection> connection;
    if (admission == Admission::serve) {
      if (tls) {
        connection = std::make_shared<Session<TlsStream>>(state, TlsStream(beast::tcp_stream(std::move(socket)), *tls));
      } else {
        connection = std::make_shared<Session<beast::tcp_stream>>(state, beast::tcp_stream(std::move(socket)));
      }
      ++state.connections;
      state.counts.open_connections = state.connections;
    } else if (admission == Admission::refuse_busy) {
      connection = std::make_shared<BusyRefusal>(state, std::move(socket));
      ++state.refusing;
      ++state.counts.refused_busy;
    } else {
      ++state.counts.closed_unanswered;
      beast::error_code ignored;
      socket.close(ignored);
      return;
    }
    state.open.emplace(connection.get(), connection);
    connection->start();
  }

  // The network thread. A handler that throws (bad_alloc, say) is logged and the loop goes on.
  void run_network() {
    for (;;) {
      try {
        state.io.run();
        return;
      } catch (const std::exception& e) {
        std::fprintf(stderr, "vimg serve: the network thread caught: %s\n", e.what());
      } catch (...) {
        std::fprintf(stderr, "vimg serve: the network thread caught an unknown exception\n");
      }
    }
  }

  std::optional<std::string> read_tls(const HttpEndpoint& endpoint) {
    if (endpoint.tls_cert_pem.empty() && endpoint.tls_key_pem.empty()) return std::nullopt;
    tls.emplace(net::ssl::context::tls_server);
    tls->set_options(net::ssl::context::default_workarounds | net::ssl::context::no_sslv2 |
                     net::ssl::context::no_sslv3 | net::ssl::context::no_tlsv1 | net::ssl::context::no_tlsv1_1);
    beast::error_code cert_ec, key_ec;
    tls->use_certificate_chain_file(endpoint.tls_cert_pem, cert_ec);
    tls->use_private_key_file(endpoint.tls_key_pem, net::ssl::context::pem, key_ec);
    if (!cert_ec && !key_ec && SSL_CTX_check_private_key(tls->native_handle()) == 1) return std::nullopt;
    tls.reset();
    return endpoint.tls_cert_pem + ", " + endpoint.tls_key_pem + ": cannot be read as a PEM certificate and its private key";
  }

  std::optional<std::string> listen(const HttpEndpoint& endpoint) {
    const std::string problem = "cannot listen on " + endpoint.host + ":" + std::to_string(endpoint.port) +
                                " (the port is in use, or the address is not this machine's)";
    beast::error_code ec;
    const net::ip::address address = net::ip::make_address(endpoint.host, ec);
    if (ec) return problem;
    acceptor.emplace(state.io);
    const tcp::endpoint where(address, static_cast<unsigned short>(endpoint.port));
    acceptor->open(where.protocol(), ec);
    if (!ec) acceptor->set_option(net::socket_base::reuse_address(true), ec);
    if (!ec) acceptor->bind(where, ec);
    if (!ec) acceptor->listen(net::socket_base::max_listen_connections, ec);
    if (ec) {
      acceptor.reset();
      return problem;
    }
    port = acceptor->local_endpoint().port();
    return std::nullopt;
  }

  // On the network thread: no more connections; the idle ones close, those with a route under way
  // send its reply first, until the grace deadline.
  void begin_stop() {
    state.stopping = true;
    beast::error_code ec;
    acceptor->close(ec);
    retry_accept->cancel();
    state.stop_deadline.emplace(state.io);
    state.stop_deadline->expires_after(state.limits().stop_grace_deadline);
    state.stop_deadline->async_wait([this](beast::error_code wait_ec) {
      if (!wait_ec) for (const auto& connection : open_connections()) connection->abort();
    });
    for (const auto& connection : open_connections()) connection->stop_gracefully();
    if (state.open.empty()) state.stop_deadline->cancel();
  }

  std::vector<std::shared_ptr<Connection>> open_connections() const {
    std::vector<std::shared_ptr<Connection>> open;
    for (const auto& [raw, weak] : state.open) {
      if (auto connection = weak.lock()) open.push_back(std::move(connection));
    }
    return open;
  }
};

HttpEngine::HttpEngine(HttpRoutes routes) : impl_(std::make_unique<Impl>(std::move(routes))) {}

HttpEngine::~HttpEngine() { stop(); }

std::optional<std::string> HttpEngine::start(const HttpEndpoint& endpoint) {
  Impl& s = *impl_;
  if (s.running) return "the server is already running";
  if (auto problem = s.read_tls(endpoint)) return problem;
  if (auto problem = s.listen(endpoint)) return problem;
  s.state.descriptor_limit = raise_descriptor_limit();
  s.state.stopping = false;
  s.state.io.restart();
  s.state.read_pool.emplace(kRouteWorkerThreads);
  s.state.write_pool.emplace(kWriteWorkerThreads);
  s.retry_accept.emplace(s.state.io);
  s.work.emplace(s.state.io.get_executor());
  s.accept();
  s.network = std::thread([&s] { s.run_network(); });
  s.running = true;
  return std::nullopt;
}

int HttpEngine::port() const { return impl_->port; }

int HttpEngine::max_connections() const {
  return connection_cap(impl_->state.limits().max_connections, impl_->state.descriptor_limit);
}

HttpEngineCounts HttpEngine::counts() const {
  const AtomicCounts& c = impl_->state.counts;
  return {c.open_connections.load(), c.refused_busy.load(), c.closed_unanswered.load(), c.routes_queued.load(),
          c.routes_dropped.load(), c.routes_failed.load(), c.refused_early.load(), c.waiting_for_room.load(),
          c.room_waits_expired.load()};
}

void HttpEngine::wake_event_streams() {
  Impl& s = *impl_;
  if (!s.running) return;
  net::post(s.state.io, [&s] {
    for (const auto& connection : s.open_connections()) connection->events_changed();
  });
}

void HttpEngine::retry_room_waiters() {
  Impl& s = *impl_;
  if (!s.running) return;
  net::post(s.state.io, [&s] { s.state.wake_room_waiters(); });
}

void HttpEngine::stop() {
  Impl& s = *impl_;
  if (!s.running.exchange(false)) return;
  std::promise<void> begun;
  net::post(s.state.io, [&s, &begun] {
    s.begin_stop();
    begun.set_value();
  });
  begun.get_future().wait();  // no new request is read from now on
  // The routes accepted (an answer being synced, or waiting for its client's turn) end; their
  // replies are posted to the network thread, which sends them and then closes (or the grace
  // deadline closes what is left).
  {
    std::unique_lock lock(s.state.pending_mutex);
    s.state.pending_changed.wait(lock, [&s] { return s.state.routes_pending == 0; });
  }
  s.state.read_pool->join();
  s.state.write_pool->join();
  s.work.reset();
  s.network.join();
  s.state.read_pool.reset();
  s.state.write_pool.reset();
  s.state.stop_deadline.reset();
  s.acceptor.reset();
  s.retry_accept.reset();
  s.state.open.clear();
  s.state.client_queues[0].clear();
  s.state.client_queues[1].clear();
  s.state.room_waiters.clear();
  s.state.room_retrying = nullptr;
  s.state.connections = s.state.refusing = 0;
  s.state.counts.open_connections = 0;
}

}  // namespace vimg::web
