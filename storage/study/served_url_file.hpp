#pragma once
// The address `vimg serve --study` serves a results folder at ("https://HOST:PORT/"), recorded in
// DIR/vimg-serve.url when the server starts so that `vimg study link DIR` can print links without
// being told it. One line of text; read back through the bounded reader, at most 4 KiB, never
// through a symbolic link.
#include <filesystem>
#include <optional>
#include <string>

namespace vimg {

inline constexpr const char* kServedUrlFile = "vimg-serve.url";

// Writes DIR/vimg-serve.url atomically; the error text, or nothing.
std::optional<std::string> record_served_url(const std::filesystem::path& dir, const std::string& base_url);

struct ServedUrlRead {
  std::optional<std::string> url;  // without its line end
  std::string file;                // DIR/vimg-serve.url
  std::string error;               // why it did not read, without the file name
};
ServedUrlRead read_served_url(const std::filesystem::path& dir);

}  // namespace vimg
