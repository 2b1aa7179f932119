#include "storage/study/served_url_file.hpp"

#include "storage/line_file.hpp"

namespace vimg {

namespace {
constexpr std::size_t kMaxServedUrlBytes = 4096;
}  // namespace

std::optional<std::string> record_served_url(const std::filesystem::path& dir, const std::string& base_url) {
  return write_line_file(dir / kServedUrlFile, base_url);
}

ServedUrlRead read_served_url(const std::filesystem::path& dir) {
  const std::filesystem::path file = dir / kServedUrlFile;
  LineFileRead read = read_line_file(file, kMaxServedUrlBytes, FinalSymlink::refuse);
  return {std::move(read.line), file.string(), std::move(read.error)};
}

}  // namespace vimg
