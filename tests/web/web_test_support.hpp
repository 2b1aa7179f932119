#pragma once
// Helpers for the web tests: the shipped examples, compiled to .vsc.
#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "storage/actuator_profile.hpp"
#include "storage/image_io.hpp"
#include "storage/vsc/vsc_image.hpp"

namespace vimg::test {

inline std::filesystem::path source_dir() { return VIMG_SOURCE_DIR; }

// Every .vimg under assets/examples, sorted.
inline std::vector<std::filesystem::path> example_images() {
  std::vector<std::filesystem::path> out;
  for (const auto& e : std::filesystem::recursive_directory_iterator(source_dir() / "assets/examples")) {
    if (e.path().extension() == ".vimg") out.push_back(e.path());
  }
  std::sort(out.begin(), out.end());
  return out;
}

inline ResponseParams shipped_response(const std::string& profile_file) {
  const ProfileLoadResult p = load_actuator_profile(source_dir() / "assets/profiles" / profile_file);
  return p.profile ? p.profile->response : ResponseParams{};
}

inline Image load_example(const std::filesystem::path& path) {
  const LoadResult r = load_image_file(path);
  return r.image ? *r.image : Image{};
}

}  // namespace vimg::test
