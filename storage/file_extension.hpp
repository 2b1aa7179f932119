#pragma once
// A file's extension in lower case ("IMAGE.PNG" -> ".png"): how every program chooses a format
// by name (vimg render/convert/import, saving an image, clip export). ASCII letters only.
#include <filesystem>
#include <string>

namespace vimg {

inline std::string lower_extension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  for (char& c : ext) c = static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
  return ext;
}

}  // namespace vimg
