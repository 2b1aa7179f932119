#pragma once
// The HTTP exchange of the server (web/server/web_server.hpp) in plain types, without the network
// library's: a request as routed, a reply, the bytes of a reply's head and of an event stream's
// chunk; the bounds every connection is held to are in web/server/http_limits.hpp.
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "web/server/http_limits.hpp"

namespace vimg::web {

struct HttpRequest {
  std::string method;  // empty when the request line could not be read
  std::string target;  // as sent
  std::string path;    // the target before '?', percent-decoded
  std::string query;   // the raw text after '?'
  std::string host, origin, content_type;  // Host, Origin, Content-Type
  std::string last_event_id;               // Last-Event-ID (an event stream reopened)
  // The fields the routes asked for (HttpRoutes::passed_fields): name and value ("" when absent).
  std::vector<std::pair<std::string, std::string>> passed_fields;
  std::string body;

  // The value of the passed field `name` ("" when absent or not asked for).
  std::string_view field(std::string_view name) const;
};

struct HttpReply {
  int status = 200;
  std::string content_type;  // empty: no Content-Type
  std::string body;          // for an event stream: its first chunk
  // A file's bytes instead of `body`: one copy shared by every reply of the file (counted in the
  // reply budget until the last reply holding it is written). For HEAD, only its size is sent.
  std::shared_ptr<const std::string> shared_body;
  std::optional<std::size_t> head_only_bytes;  // HEAD of a file: the Content-Length, no body
  std::vector<std::pair<std::string, std::string>> headers;  // any further header
  bool close = false;                                        // Connection: close after this reply
  bool event_stream = false;  // chunked, and the stream's messages follow (web/server/event_stream.hpp)
  std::int64_t stream_cursor = 0;
  // The route found no room (the reply budget full, web/server/file_copies.hpp): the engine runs it
  // again in its turn when the copies change (HttpEngine::retry_room_waiters: one freed, or one made
  // that it may share), holding no reply meanwhile, and sends this reply (a 503) only once
  // HttpLimits::reply_budget_wait has passed since it first waited.
  bool wait_for_room = false;

  std::string_view body_bytes() const { return shared_body ? std::string_view(*shared_body) : std::string_view(body); }
  std::size_t content_length() const { return head_only_bytes ? *head_only_bytes : body_bytes().size(); }
};

// A reply of `status` with `body` of `content_type`.
HttpReply body_reply(int status, std::string content_type, std::string body);
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
std::chrono::milliseconds write_deadline(const HttpLimits& limits, std::size_t bytes);

// The status for a header that ran past kMaxHeaderBytes: 414 when its first line (the request
// line) is longer than kMaxRequestLineBytes or has not ended yet, 400 otherwise.
int oversized_header_status(std::string_view received);

}  // namespace vimg::web
