#pragma once
// The Content-Type the server sends for a file of a built site, from its extension: what a
// browser needs to run it (application/wasm for WebAssembly's streaming compile, a JavaScript type
// for modules and worklets). Anything else is application/octet-stream (with the server's
// X-Content-Type-Options: nosniff, the browser never guesses).
#include <filesystem>
#include <string>

namespace vimg::web {

std::string content_type_of(const std::filesystem::path& file);

}  // namespace vimg::web
