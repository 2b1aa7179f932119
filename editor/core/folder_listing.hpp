#pragma once
// What the editor's file chooser lists: one folder's sub-folders and the files a filter accepts,
// sorted for reading, and the path a designer types, resolved against the folder shown. No GUI
// code (the ImGui view is editor/file_chooser.*). The recent folders are a RecentFiles list
// (recent_files.hpp) of folders, in the config folder.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace vimg::editor {

// At most this many entries of one folder are listed (a folder of a million files costs no more
// than this); the listing says when it was cut.
inline constexpr std::size_t kMaxFolderEntries = 5000;

// A filter: a label and the extensions it accepts (lower case, with the dot); none accepts all.
struct FileFilter {
  std::string label;
  std::vector<std::string> extensions;
};
// Open/Import: images (.vimg .xml .png), XML (.vimg .xml), PNG (.png), all files.
std::vector<FileFilter> image_filters();
// Import: drawings and pictures (.svg .png), SVG (.svg), PNG (.png), all files.
std::vector<FileFilter> import_filters();
// Save as: XML (.vimg .xml), PNG (.png).
std::vector<FileFilter> save_filters();
// Save gesture: CSV (.csv).
std::vector<FileFilter> gesture_filters();

// Whether the file name ends in one of the extensions, in any case ("A.PNG" is a .png).
bool accepts(const FileFilter& filter, std::string_view file_name);

struct FolderEntry {
  std::string name;
  bool folder = false;
  std::uintmax_t size_bytes = 0;  // files only
  friend bool operator==(const FolderEntry&, const FolderEntry&) = default;
};

struct FolderListing {
  std::filesystem::path folder;       // absolute, normal form
  std::vector<FolderEntry> entries;   // folders first, then files; each by name, ignoring case
  bool truncated = false;             // more than kMaxFolderEntries
  std::optional<std::string> error;   // the folder could not be read (entries empty)
};

// Lists `folder`: its sub-folders and the regular files `filter` accepts (symbolic links are
// followed; entries that vanish or cannot be examined are left out). Names starting with '.' are
// left out unless `show_hidden`.
FolderListing list_folder(const std::filesystem::path& folder, const FileFilter& filter, bool show_hidden = false);

// The folder above (the root stays the root).
std::filesystem::path parent_folder(const std::filesystem::path& folder);

// What the designer typed, as a path: "~" and "~/..." from `home`, a relative path against
// `folder`, an absolute one as it is; in normal form. Empty text gives nothing.
std::optional<std::filesystem::path> resolve_typed_path(std::string_view typed, const std::filesystem::path& folder,
                                                        const std::filesystem::path& home);

// When saving: a name without any extension gets the filter's first ("picture" with the PNG
// filter becomes "picture.png"); a name with one keeps it ("a.png" stays a PNG under any filter:
// the format follows the extension).
std::string with_extension(const std::string& name, const FileFilter& filter);

}  // namespace vimg::editor
