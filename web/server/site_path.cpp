#include "web/server/site_path.hpp"

#include <system_error>
#include <vector>

namespace vimg::web {

namespace fs = std::filesystem;

namespace {

SiteLookup refused(SiteLookupStatus status, std::string reason) {
  SiteLookup lookup;
  lookup.status = status;
  lookup.reason = std::move(reason);
  return lookup;
}

// Whether `path` (canonical) is `root` itself or lies below it.
bool is_within(const fs::path& root, const fs::path& path) {
  auto r = root.begin();
  auto p = path.begin();
  for (; r != root.end(); ++r, ++p) {
    if (p == path.end() || *r != *p) return false;
  }
  return true;
}

// The canonical form of `candidate` if it exists and stays inside `root`.
SiteLookup resolve_inside(const fs::path& root, const fs::path& candidate) {
  std::error_code ec;
  const fs::path resolved = fs::weakly_canonical(candidate, ec);
  if (ec) return refused(SiteLookupStatus::not_found, "cannot be resolved: " + ec.message());
  if (!is_within(root, resolved)) return refused(SiteLookupStatus::forbidden, "a symbolic link leads out of the site");
  SiteLookup lookup;
  lookup.status = SiteLookupStatus::found;
  lookup.file = resolved;
  return lookup;
}

}  // namespace

SiteLookup find_site_file(const fs::path& site_root, std::string_view url_path) {
  if (url_path.empty() || url_path.front() != '/') return refused(SiteLookupStatus::forbidden, "not an absolute path");
  if (url_path.find('\0') != std::string_view::npos) return refused(SiteLookupStatus::forbidden, "a NUL in the path");
  if (url_path.find('\\') != std::string_view::npos) return refused(SiteLookupStatus::forbidden, "a backslash in the path");
  fs::path candidate = site_root;
  std::size_t start = 1;
  while (start <= url_path.size()) {
    std::size_t end = url_path.find('/', start);
    if (end == std::string_view::npos) end = url_path.size();
    const std::string_view segment = url_path.substr(start, end - start);
    start = end + 1;
    if (segment.empty()) continue;
    if (segment == ".." || segment == ".") return refused(SiteLookupStatus::forbidden, "'.' or '..' in the path");
    if (segment.front() == '.') return refused(SiteLookupStatus::not_found, "a hidden file");
    candidate /= std::string(segment);
  }
  SiteLookup lookup = resolve_inside(site_root, candidate);
  if (lookup.status != SiteLookupStatus::found) return lookup;
  std::error_code ec;
  if (fs::is_directory(fs::symlink_status(lookup.file, ec))) {
    lookup = resolve_inside(site_root, lookup.file / "index.html");
    if (lookup.status != SiteLookupStatus::found) return lookup;
  }
  const fs::file_status status = fs::symlink_status(lookup.file, ec);
  if (ec || !fs::exists(status)) return refused(SiteLookupStatus::not_found, "no such file");
  if (fs::is_directory(status)) return refused(SiteLookupStatus::not_found, "a folder without index.html");
  if (!fs::is_regular_file(status)) return refused(SiteLookupStatus::not_found, "not a regular file");
  return lookup;
}

}  // namespace vimg::web
