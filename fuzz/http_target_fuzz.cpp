// The server's own handling of a request's text (web/server/http_message.hpp; the HTTP syntax
// itself is Boost.Beast's parser): a target split into its path, percent-decoded, and its raw
// query; the status of a header that ran past its bound; a chunk of an event stream. Properties:
// decoding never lengthens the path, a target without '?' has no query, the oversized header's
// status is 414 or 400, and a chunk says its own size.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "web/server/http_message.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  vimg::web::HttpRequest request;
  vimg::web::split_target(text, request);
  const std::size_t question = text.find('?');
  if (request.path.size() > text.substr(0, question).size()) std::abort();
  if (question == std::string::npos && !request.query.empty()) std::abort();
  if (question != std::string::npos && request.query != text.substr(question + 1)) std::abort();
  const int status = vimg::web::oversized_header_status(text);
  if (status != 400 && status != 414) std::abort();
  const std::string chunk = vimg::web::format_chunk(text);
  if (std::strtoull(chunk.c_str(), nullptr, 16) != size || chunk.size() < size + 4) std::abort();
  return 0;
}
