#include "web/server/http_message.hpp"

#include <cstdio>

namespace vimg::web {

namespace {

const char* reason_of(int status) {
  switch (status) {
    case 100: return "Continue";
    case 200: return "OK";
    case 400: return "Bad Request";
    case 403: return "Forbidden";
    case 404: return "Not Found";
    case 405: return "Method Not Allowed";
    case 408: return "Request Timeout";
    case 409: return "Conflict";
    case 413: return "Payload Too Large";
    case 414: return "URI Too Long";
    case 429: return "Too Many Requests";
    case 500: return "Internal Server Error";
    case 503: return "Service Unavailable";
    default: return status < 400 ? "OK" : "Error";
  }
}

}  // namespace

int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

std::string_view HttpRequest::field(std::string_view name) const {
  for (const auto& [passed, value] : passed_fields) {
    if (passed == name) return value;
  }
  return {};
}

HttpReply body_reply(int status, std::string content_type, std::string body) {
  HttpReply reply;
  reply.status = status;
  reply.content_type = std::move(content_type);
  reply.body = std::move(body);
  return reply;
}

HttpReply text_reply(int status, const std::string& text) {
  return body_reply(status, "text/plain; charset=utf-8", text + "\n");
}

std::string format_reply_head(const HttpReply& reply, std::size_t body_bytes) {
  std::string head = "HTTP/1.1 " + std::to_string(reply.status) + " " + reason_of(reply.status) + "\r\n";
  head += "Cache-Control: no-store\r\nX-Content-Type-Options: nosniff\r\n";
  if (!reply.content_type.empty()) head += "Content-Type: " + reply.content_type + "\r\n";
  for (const auto& [name, value] : reply.headers) head += name + ": " + value + "\r\n";
  if (reply.event_stream) {
    head += "Transfer-Encoding: chunked\r\n";
  } else {
    head += "Content-Length: " + std::to_string(body_bytes) + "\r\n";
  }
  if (reply.close) head += "Connection: close\r\n";
  return head + "\r\n";
}

std::string format_chunk(std::string_view data) {
  char size[24];
  std::snprintf(size, sizeof size, "%zx\r\n", data.size());
  return size + std::string(data) + "\r\n";
}

std::string percent_decode_path(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '%' && i + 2 < text.size() && hex_digit(text[i + 1]) >= 0 && hex_digit(text[i + 2]) >= 0) {
      out += static_cast<char>(hex_digit(text[i + 1]) * 16 + hex_digit(text[i + 2]));
      i += 2;
    } else {
      out += text[i];
    }
  }
  return out;
}

void split_target(const std::string& target, HttpRequest& request) {
  const std::size_t question = target.find('?');
  request.path = percent_decode_path(std::string_view(target).substr(0, question));
  request.query = question == std::string::npos ? std::string() : target.substr(question + 1);
}

std::chrono::milliseconds write_deadline(const HttpLimits& limits, std::size_t bytes) {
  const std::size_t rate = limits.write_bytes_per_second == 0 ? 1 : limits.write_bytes_per_second;
  return limits.write_deadline + std::chrono::seconds(bytes / rate);
}

int oversized_header_status(std::string_view received) {
  const std::size_t line_end = received.find("\r\n");
  return line_end == std::string_view::npos || line_end > kMaxRequestLineBytes ? 414 : 400;
}

}  // namespace vimg::web
