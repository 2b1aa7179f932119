#pragma once
// The HTTP exchange of the server (web/server/web_server.hpp) in plain types, without the network
// library's: a request as routed, a reply, the bytes of a reply's head and of an event stream's
// chunk, and the bounds every connection is held to (docs/web.md, "Serving").
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace vimg::web {

// Bounds of one connection. A participant's page sends its request at once (a few hundred bytes);
// a client that trickles its header, says nothing, or sends more hits these long before.
inline constexpr std::chrono::seconds kHeaderDeadline{5};   // connect or keep-alive start to end of the header
inline constexpr std::chrono::seconds kBodyDeadline{5};     // end of the header to end of the body
inline constexpr std::chrono::seconds kTlsHandshakeDeadline{5};
inline constexpr std::chrono::seconds kWriteDeadline{10};   // a reply's write, plus 1 s per kWriteBytesPerSecond
inline constexpr std::size_t kWriteBytesPerSecond = 256 * 1024;
inline constexpr std::chrono::seconds kClosingDeadline{1};  // reading what is left before closing
inline constexpr std::size_t kMaxRequestLineBytes = 8192;   // beyond: 414 (cpp-httplib's bound, kept)
inline constexpr std::size_t kMaxHeaderLineBytes = 8192;    // beyond: 400
inline constexpr std::size_t kMaxHeaderBytes = 16384;       // the whole header; beyond: 414 or 400
// Connections open at once (participants, pages, and anything else); one more is closed at once
// with 503. Lowered to what the process's descriptor limit allows (raised to its hard limit).
inline constexpr int kMaxConnections = 4000;
// The threads that run the routes (files, the study API); the network is one thread of its own.
inline constexpr int kRouteWorkerThreads = 4;

struct HttpRequest {
  std::string method;  // empty when the request line could not be read
  std::string target;  // as sent
  std::string path;    // the target before '?', percent-decoded
  std::string query;   // the raw text after '?'
  std::string host, origin, key, content_type;  // Host, Origin, X-Vimg-Key, Content-Type
  std::string body;
};

struct HttpReply {
  int status = 200;
  std::string content_type;  // empty: no Content-Type
  std::string body;          // for an event stream: its first chunk
  std::vector<std::pair<std::string, std::string>> headers;  // any further header
  bool close = false;                                        // Connection: close after this reply
  bool event_stream = false;  // chunked, and the stream's messages follow (web/server/event_stream.hpp)
  std::int64_t stream_cursor = 0;
};

// "text\n" as text/plain.
HttpReply text_reply(int status, const std::string& text);

// The head of `reply` for a body of `body_bytes` (Content-Length; an event stream is chunked
// instead), with Cache-Control: no-store and X-Content-Type-Options: nosniff.
std::string format_reply_head(const HttpReply& reply, std::size_t body_bytes);
// One chunk of a chunked body ("" ends the body).
std::string format_chunk(std::string_view data);

// The value of a hexadecimal digit (either case), -1 for any other character.
int hex_digit(char c);

// %XX decoded (a bad escape stays as it is); '+' is not a space in a path.
std::string percent_decode_path(std::string_view text);
// The path and query of a request target.
void split_target(const std::string& target, HttpRequest& request);

// How long a reply of `bytes` may take to write.
std::chrono::seconds write_deadline(std::size_t bytes);

// The status for a header that ran past kMaxHeaderBytes: 414 when its first line (the request
// line) is longer than kMaxRequestLineBytes or has not ended yet, 400 otherwise.
int oversized_header_status(std::string_view received);

}  // namespace vimg::web
