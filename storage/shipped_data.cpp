#include "storage/shipped_data.hpp"

#include <algorithm>
#include <cstdlib>
#include <system_error>

namespace vimg {
namespace fs = std::filesystem;

namespace {

bool holds_profiles(const fs::path& dir) {
  std::error_code ec;
  return fs::is_directory(dir / "profiles", ec);
}

}  // namespace

std::optional<fs::path> find_shipped_data_dir(const char* environment_value, const fs::path& executable) {
  if (environment_value != nullptr && *environment_value != '\0') return fs::path(environment_value);
  fs::path dir = executable.parent_path();
  for (int level = 0; level < 3 && !dir.empty(); ++level) {
    const fs::path candidate = dir.parent_path() / "share" / "vibroimage";
    if (holds_profiles(candidate)) return candidate;
    if (dir == dir.parent_path()) break;
    dir = dir.parent_path();
  }
  return std::nullopt;
}

std::optional<fs::path> shipped_data_dir() {
  std::error_code ec;
  const fs::path executable = fs::read_symlink("/proc/self/exe", ec);
  return find_shipped_data_dir(std::getenv(kShippedDataEnvironmentVariable), ec ? fs::path() : executable);
}

std::string shipped_data_help() {
  return std::string("the shipped data (profiles, examples) were not found: set ") + kShippedDataEnvironmentVariable +
         " to the folder that holds profiles/ (PREFIX/share/vibroimage after an install)";
}

fs::path resolve_profile_argument(const fs::path& argument) {
  const bool bare_name = !argument.empty() && !argument.has_parent_path() && !argument.has_extension() &&
                         argument != "." && argument != "..";
  if (!bare_name) return argument;
  std::error_code ec;
  if (fs::exists(argument, ec)) return argument;
  const std::optional<fs::path> data = shipped_data_dir();
  if (!data) return argument;
  const fs::path shipped = *data / "profiles" / (argument.string() + ".xml");
  return fs::exists(shipped, ec) ? shipped : argument;
}

std::vector<std::string> shipped_profile_names() {
  std::vector<std::string> names;
  const std::optional<fs::path> data = shipped_data_dir();
  if (!data) return names;
  std::error_code ec;
  for (fs::directory_iterator it(*data / "profiles", ec), end; !ec && it != end; it.increment(ec)) {
    if (it->path().extension() == ".xml") names.push_back(it->path().stem().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

}  // namespace vimg
