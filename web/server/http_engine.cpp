#include "web/server/http_engine.hpp"

#include <sys/resource.h>

#include <algorithm>
#include <atomic>
#include <boost/asio/executor_work_guard.hpp>
#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/post.hpp>
#include <boost/asio/ssl.hpp>
#include <boost/asio/steady_timer.hpp>
#include <boost/asio/thread_pool.hpp>
#include <future>
#include <thread>
#include <unordered_map>

#include "web/server/http_connection.hpp"

namespace vimg::web {

namespace {

// Raises the soft limit of open descriptors to the hard one; the connections the limit then allows
// (a few descriptors are kept for files, the watcher and the log).
int connections_the_descriptors_allow() {
  rlimit limit{};
  if (getrlimit(RLIMIT_NOFILE, &limit) != 0) return kMaxConnections;
  if (limit.rlim_cur < limit.rlim_max) {
    limit.rlim_cur = limit.rlim_max;
    setrlimit(RLIMIT_NOFILE, &limit);
    getrlimit(RLIMIT_NOFILE, &limit);
  }
  constexpr rlim_t kKeptDescriptors = 64;
  if (limit.rlim_cur == RLIM_INFINITY || limit.rlim_cur >= kMaxConnections + kKeptDescriptors) return kMaxConnections;
  return std::max(16, static_cast<int>(limit.rlim_cur) - static_cast<int>(kKeptDescriptors));
}

// A connection beyond the limit: a 503 if the socket takes it at once (it always has room for a few
// bytes), then closed. Never waited for.
void refuse_busy(tcp::socket& socket, bool tls) {
  beast::error_code ec;
  if (!tls) {
    static const std::string kBusy = [] {
      HttpReply reply = text_reply(503, "the server is busy (too many connections); try again");
      reply.close = true;
      return format_reply_head(reply, reply.body.size()) + reply.body;
    }();
    socket.non_blocking(true, ec);
    socket.write_some(net::buffer(kBusy), ec);
    socket.shutdown(tcp::socket::shutdown_send, ec);
  }
  socket.close(ec);
}

}  // namespace

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
      if (static_cast<int>(state.open.size()) >= state.max_connections) {
        refuse_busy(socket, tls.has_value());
      } else {
        std::shared_ptr<Connection> connection;
        if (tls) {
          connection = std::make_shared<Session<TlsStream>>(state, TlsStream(beast::tcp_stream(std::move(socket)), *tls));
        } else {
          connection = std::make_shared<Session<beast::tcp_stream>>(state, beast::tcp_stream(std::move(socket)));
        }
        state.open.emplace(connection.get(), connection);
        connection->start();
      }
      accept();
    });
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
};

HttpEngine::HttpEngine(HttpRoutes routes) : impl_(std::make_unique<Impl>(std::move(routes))) {}

HttpEngine::~HttpEngine() { stop(); }

std::optional<std::string> HttpEngine::start(const HttpEndpoint& endpoint) {
  Impl& s = *impl_;
  if (s.running) return "the server is already running";
  if (auto problem = s.read_tls(endpoint)) return problem;
  if (auto problem = s.listen(endpoint)) return problem;
  s.state.max_connections = connections_the_descriptors_allow();
  s.state.stopping = false;
  s.state.io.restart();
  s.state.pool.emplace(kRouteWorkerThreads);
  s.retry_accept.emplace(s.state.io);
  s.work.emplace(s.state.io.get_executor());
  s.accept();
  s.network = std::thread([&s] { s.state.io.run(); });
  s.running = true;
  return std::nullopt;
}

int HttpEngine::port() const { return impl_->port; }

int HttpEngine::max_connections() const { return impl_->state.max_connections; }

void HttpEngine::wake_event_streams() {
  Impl& s = *impl_;
  if (!s.running) return;
  net::post(s.state.io, [&s] {
    for (const auto& [raw, weak] : s.state.open) {
      if (const auto connection = weak.lock()) connection->events_changed();
    }
  });
}

void HttpEngine::stop() {
  Impl& s = *impl_;
  if (!s.running.exchange(false)) return;
  std::promise<void> closed;
  net::post(s.state.io, [&s, &closed] {
    s.state.stopping = true;
    beast::error_code ec;
    s.acceptor->close(ec);
    s.retry_accept->cancel();
    std::vector<std::shared_ptr<Connection>> open;
    for (const auto& [raw, weak] : s.state.open) {
      if (auto connection = weak.lock()) open.push_back(std::move(connection));
    }
    for (const auto& connection : open) connection->abort();
    closed.set_value();
  });
  closed.get_future().wait();  // no route is handed a request from now on
  s.state.pool->join();  // the routes under way end (an answer is on disk); their replies are dropped
  s.work.reset();
  s.network.join();
  s.state.pool.reset();
  s.acceptor.reset();
  s.retry_accept.reset();
}

}  // namespace vimg::web
