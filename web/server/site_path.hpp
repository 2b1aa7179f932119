#pragma once
// Which file of a built site a request names, or why none (docs/web-serving.md, "Serving"). The server is
// read-only and serves the site's folder only:
//   - the URL path is taken already percent-decoded (so "%2e%2e" has become ".."); a ".." or "."
//     segment, a NUL or a backslash is forbidden, never resolved;
//   - a segment starting with "." (a hidden file, an atomic writer's temporary) is not found;
//   - the path is resolved through every symbolic link (weakly_canonical) and must still lie in
//     the site's folder: a link that leads out of it is forbidden;
//   - a folder gives its index.html (checked the same way) when it has one; there is no listing;
//   - only regular files are found (never a FIFO, a device or a socket).
#include <filesystem>
#include <string>
#include <string_view>

namespace vimg::web {

enum class SiteLookupStatus { found, forbidden, not_found };

struct SiteLookup {
  SiteLookupStatus status = SiteLookupStatus::not_found;
  std::filesystem::path file;  // when found: the canonical path of the regular file to send
  std::string reason;          // otherwise: why, for the log ("'..' in the path", ...)
};

// `site_root` must be canonical (std::filesystem::canonical of the site's folder).
SiteLookup find_site_file(const std::filesystem::path& site_root, std::string_view url_path);

}  // namespace vimg::web
