#include "storage/named_file.hpp"

#include <string>
#include <system_error>

namespace vimg {

namespace {

namespace fs = std::filesystem;

// True when `path`, made lexically normal, stays at or below the folder it is relative to.
bool stays_below(const fs::path& relative) {
  const fs::path normal = relative.lexically_normal();
  return normal.empty() || *normal.begin() != "..";
}

}  // namespace

NamedFileReadResult read_named_file(const fs::path& folder, std::string_view name, std::size_t max_bytes,
                                    const NamedFileOptions& options, std::string_view what_folder) {
  NamedFileReadResult result;
  const fs::path base = folder.empty() ? fs::path(".") : folder;
  const fs::path named(name);
  result.path = named.is_absolute() ? named : folder / named;
  if (name.empty()) {
    result.read.error = "is empty, expected a file name";
    return result;
  }
  if (!options.allow_outside_folder) {
    const std::string outside = "leads outside " + std::string(what_folder) + " (data files must be in it or below it " +
                                "unless loading is allowed to leave it)";
    if (named.is_absolute() || named.has_root_name() || !stays_below(named)) {
      result.read.error = outside;
      return result;
    }
    // A symbolic link on the way (not the file itself, which is never followed) may lead elsewhere.
    std::error_code ec;
    const fs::path real_base = fs::weakly_canonical(base, ec);
    const fs::path real_parent = ec ? fs::path() : fs::weakly_canonical((base / named).parent_path(), ec);
    if (ec || !stays_below(real_parent.lexically_relative(real_base)) || real_parent.lexically_relative(real_base).empty()) {
      result.read.error = outside;
      return result;
    }
  }
  result.read = read_regular_file(result.path, max_bytes, FinalSymlink::refuse);
  return result;
}

}  // namespace vimg
