#include "editor/core/recovery.hpp"

#include <cstdlib>
#include <fstream>
#include <system_error>

#include "storage/image_io.hpp"

namespace vimg::editor {

RecoveryStore::RecoveryStore(std::filesystem::path dir) : dir_(std::move(dir)) {}

std::filesystem::path RecoveryStore::default_dir() {
  if (const char* state = std::getenv("XDG_STATE_HOME"); state && *state) {
    return std::filesystem::path(state) / "vimg-editor";
  }
  if (const char* home = std::getenv("HOME"); home && *home) {
    return std::filesystem::path(home) / ".local" / "state" / "vimg-editor";
  }
  return std::filesystem::temp_directory_path() / "vimg-editor";
}

std::optional<std::string> RecoveryStore::save(const Image& image, const std::filesystem::path& origin) {
  std::error_code ec;
  std::filesystem::create_directories(dir_, ec);
  if (ec) return dir_.string() + ": cannot create the recovery folder: " + ec.message();
  {
    const std::filesystem::path tmp = origin_file().string() + ".tmp";
    std::ofstream out(tmp, std::ios::trunc);
    out << origin.string() << '\n';
    out.close();
    if (!out) return tmp.string() + ": cannot write";
    std::filesystem::rename(tmp, origin_file(), ec);
    if (ec) return origin_file().string() + ": " + ec.message();
  }
  return save_image_file(image, file());
}

bool RecoveryStore::exists() const {
  std::error_code ec;
  return std::filesystem::is_regular_file(file(), ec);
}

std::filesystem::path RecoveryStore::recorded_origin() const {
  std::ifstream in(origin_file());
  std::string line;
  std::getline(in, line);
  return line;
}

void RecoveryStore::discard() {
  std::error_code ec;
  std::filesystem::remove(file(), ec);
  std::filesystem::remove(origin_file(), ec);
}

}  // namespace vimg::editor
