#include "editor/core/folder_listing.hpp"

#include <algorithm>
#include <cctype>
#include <system_error>

namespace vimg::editor {
namespace {

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

bool name_less(const FolderEntry& a, const FolderEntry& b) {
  if (a.folder != b.folder) return a.folder;
  const std::string la = lower(a.name), lb = lower(b.name);
  return la != lb ? la < lb : a.name < b.name;
}

}  // namespace

std::vector<FileFilter> image_filters() {
  return {{"Images (.vimg, .xml, .png)", {".vimg", ".xml", ".png"}},
          {"XML (.vimg, .xml)", {".vimg", ".xml"}},
          {"PNG with the XML inside (.png)", {".png"}},
          {"All files", {}}};
}

std::vector<FileFilter> import_filters() {
  return {{"Drawings and pictures (.svg, .png)", {".svg", ".png"}},
          {"SVG drawings (.svg)", {".svg"}},
          {"PNG pictures (.png)", {".png"}},
          {"All files", {}}};
}

std::vector<FileFilter> save_filters() {
  return {{"XML (.vimg, .xml)", {".vimg", ".xml"}}, {"PNG with the XML inside (.png)", {".png"}}};
}

std::vector<FileFilter> gesture_filters() { return {{"Gesture CSV (.csv)", {".csv"}}}; }

bool accepts(const FileFilter& filter, std::string_view file_name) {
  if (filter.extensions.empty()) return true;
  const std::string name = lower(file_name);
  return std::any_of(filter.extensions.begin(), filter.extensions.end(), [&](const std::string& ext) {
    return name.size() > ext.size() && name.compare(name.size() - ext.size(), ext.size(), ext) == 0;
  });
}

FolderListing list_folder(const std::filesystem::path& folder, const FileFilter& filter, bool show_hidden) {
  namespace fs = std::filesystem;
  FolderListing listing;
  std::error_code ec;
  fs::path absolute = fs::absolute(folder, ec);
  listing.folder = (ec ? folder : absolute).lexically_normal();
  if (listing.folder.has_filename() == false && listing.folder != listing.folder.root_path()) {
    listing.folder = listing.folder.parent_path();  // "a/b/" as "a/b"
  }
  fs::directory_iterator it(listing.folder, fs::directory_options::skip_permission_denied, ec);
  if (ec) {
    listing.error = listing.folder.string() + ": " + ec.message();
    return listing;
  }
  for (const fs::directory_iterator end; it != end; it.increment(ec)) {
    if (ec) break;
    const std::string name = it->path().filename().string();
    if (!show_hidden && !name.empty() && name.front() == '.') continue;
    std::error_code type_ec;
    const fs::file_status status = it->status(type_ec);  // follows links
    if (type_ec) continue;
    FolderEntry entry{name, fs::is_directory(status), 0};
    if (!entry.folder) {
      if (!fs::is_regular_file(status) || !accepts(filter, name)) continue;
      std::error_code size_ec;
      const std::uintmax_t size = it->file_size(size_ec);
      entry.size_bytes = size_ec ? 0 : size;
    }
    if (listing.entries.size() == kMaxFolderEntries) {
      listing.truncated = true;
      break;
    }
    listing.entries.push_back(std::move(entry));
  }
  std::sort(listing.entries.begin(), listing.entries.end(), name_less);
  return listing;
}

std::filesystem::path parent_folder(const std::filesystem::path& folder) {
  const std::filesystem::path normal = folder.lexically_normal();
  if (normal == normal.root_path()) return normal;
  std::filesystem::path parent = normal.has_filename() ? normal.parent_path() : normal.parent_path().parent_path();
  return parent.empty() ? normal : parent;
}

std::optional<std::filesystem::path> resolve_typed_path(std::string_view typed, const std::filesystem::path& folder,
                                                        const std::filesystem::path& home) {
  if (typed.empty()) return std::nullopt;
  std::filesystem::path p;
  if (typed == "~") {
    p = home;
  } else if (typed.size() >= 2 && typed.substr(0, 2) == "~/") {
    p = home / std::string(typed.substr(2));
  } else {
    p = std::filesystem::path(std::string(typed));
    if (p.is_relative()) p = folder / p;
  }
  return p.lexically_normal();
}

std::string with_extension(const std::string& name, const FileFilter& filter) {
  if (filter.extensions.empty() || !std::filesystem::path(name).extension().empty()) return name;
  return name + filter.extensions.front();
}

}  // namespace vimg::editor
