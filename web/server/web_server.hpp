#pragma once
// The read-only server of a built web site (docs/web-serving.md, "Serving"), event driven on Boost.Beast
// (web/server/http_engine.hpp: one network thread, the routes on a few workers, the writing ones
// apart; an idle or slow connection costs no worker):
//   - GET and HEAD only; any other method gets 405 with "Allow: GET, HEAD" and the connection closes;
//   - the site's folder only (web/server/site_path.hpp): '..' (also percent-encoded) and symbolic
//     links out of the folder are forbidden (403), a folder without index.html is not found (404),
//     nothing is ever listed;
//   - bounded requests and connections (web/server/http_message.hpp, HttpLimits);
//     a file beyond kMaxServedFileBytes is not served (500); a file is sent from one copy shared by
//     every reply of it, within the reply budget (web/server/file_copies.hpp): a request that finds
//     it full waits for room, holding no reply, up to HttpLimits::reply_budget_wait, then 503;
//   - every response says Cache-Control: no-store (a page always fetches the latest save) and
//     X-Content-Type-Options: nosniff; the Content-Type comes from web/server/content_type.hpp;
//   - /events is the Server-Sent Events stream of the images' changes (web/server/event_stream.hpp),
//     without an `api` only (a study publishes nothing: there /events is 404);
//   - one log line per request: "METHOD PATH STATUS BYTES" (control characters escaped; the query
//     is never logged); a route that throws answers 500 and logs "METHOD PATH: failed: WHAT";
//   - with an `api` (vimg serve --study, web/study_server/), GET of /api/... and POST of the paths
//     in `api_post_paths` go to it instead; every other POST is refused as above; the api is called
//     from several workers at once; `api_screen`, when given, sees each of these requests first, on
//     the network thread, before it waits for anything (HttpRoutes::screen);
//   - with `tls_cert_pem` and `tls_key_pem`, HTTPS (a secure context on a LAN).
// The server runs on threads of its own between start() and stop() (or the destructor).
#include <cstddef>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "web/server/http_limits.hpp"
#include "web/server/http_message.hpp"

namespace vimg::web {

inline constexpr std::size_t kMaxRequestBodyBytes = 4096;
inline constexpr std::size_t kMaxServedFileBytes = std::size_t{64} << 20;

// The API's request and reply are the server's own (web/server/http_message.hpp, without the
// library's types), the request passed as it was read: its method (GET, HEAD or POST), decoded path,
// raw query, Host, Origin, Content-Type, body, and the key field kApiKeyField (request.field()).
inline constexpr const char* kApiKeyField = "X-Vimg-Key";
using ApiRequest = HttpRequest;
using ApiReply = HttpReply;
using ApiHandler = std::function<ApiReply(const ApiRequest&)>;

struct WebServerOptions {
  std::filesystem::path site_dir;
  std::string host = "127.0.0.1";  // "0.0.0.0" for the LAN (vimg serve --lan)
  int port = 0;                    // 0: any free port (port() says which)
  // Receives each log line (without its newline); by default they go to stderr.
  std::function<void(const std::string&)> log_line;
  ApiHandler api;                           // empty: no /api/ (plain vimg serve)
  // The API's cheap refusals (no file, no participant's lock: a wrong key, the rate limit), run on
  // the network thread as each request to the api arrives: a reply at once, or nothing to pass it
  // to `api`.
  std::function<std::optional<ApiReply>(const ApiRequest&)> api_screen;
  std::vector<std::string> api_post_paths;  // the only paths a POST may reach
  std::filesystem::path tls_cert_pem, tls_key_pem;  // both empty: plain HTTP
  // The files the api keeps open (participants' trial files): they share the descriptors with the
  // connections (web/server/descriptor_budget.hpp). Called from the network thread.
  std::function<int()> api_files_held;
  HttpLimits limits;  // the documented bounds; tests shrink some
};

class WebServer {
 public:
  explicit WebServer(WebServerOptions options);
  ~WebServer();  // stop()
  WebServer(const WebServer&) = delete;
  WebServer& operator=(const WebServer&) = delete;

  // Binds the address and serves from a thread of its own. Returns the problem (a folder that is
  // not there, an address in use), or nothing once the server accepts connections.
  std::optional<std::string> start();
  int port() const;
  bool running() const;

  // Tells every open page that images/NAME.vsc was rewritten ("event: image", "data: NAME").
  void publish_image_changed(const std::string& name);
  int open_event_streams() const;
  HttpEngineCounts counts() const;
  std::size_t reply_bytes_held() const;  // the file copies replies hold now (within the reply budget)

  // Ends the open event streams, closes the listening socket and the idle connections, lets the
  // routes under way (an answer being synced) end and send their replies, and joins the threads.
  // Idempotent.
  void stop();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace vimg::web
