#include "storage/import/svg_ids.hpp"

namespace vimg::svg {

namespace {

std::string valid_id(const char* raw) {
  std::string id;
  for (const char* p = raw; *p != '\0' && id.size() < 64; ++p) {
    const char c = *p;
    const bool digit = c >= '0' && c <= '9';
    const bool ok = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_' || digit ||
                    (!id.empty() && (c == '.' || c == '-'));
    if (id.empty() && digit) id += '_';
    id += ok ? c : '_';
  }
  return id;
}

}  // namespace

std::string UniqueIds::take(const char* raw) {
  if (raw == nullptr || *raw == '\0') return {};
  const std::string id = valid_id(raw);
  ++attempts_;
  if (taken_.insert(id).second) return id;
  int& suffix = next_suffix_.try_emplace(id, 2).first->second;
  for (;; ++suffix) {
    ++attempts_;
    std::string candidate = id + "-" + std::to_string(suffix);
    if (taken_.insert(candidate).second) {
      ++suffix;
      return candidate;
    }
  }
}

void UniqueIds::release(const std::string& id) {
  if (!id.empty()) taken_.erase(id);
}

}  // namespace vimg::svg
