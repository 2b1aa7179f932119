// The loaders of the touch trace, the volume scene and the NRRD volume say why a file could not be
// read as every loader does (storage/load_file.hpp): one diagnostic at line 0 with read_file's
// words, "FILE: error: cannot open: REASON" for a missing file and "FILE: error: is not a regular
// file (a FIFO)" for a FIFO, never a wording of their own.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "storage/diagnostic.hpp"
#include "storage/touch_trace/evdev_trace.hpp"
#include "storage/volume/nrrd_volume.hpp"
#include "storage/volume/volume_scene_io.hpp"

namespace vimg {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> messages(const std::vector<Diagnostic>& diagnostics) {
  std::vector<std::string> out;
  for (const auto& d : diagnostics) out.push_back(d.to_string());
  return out;
}

TEST(LoaderReadErrors, TheLoadersWordAMissingFileAndAFifoAsEveryLoaderDoes) {
  const fs::path dir = fs::temp_directory_path() / ("vimg_loader_read_errors_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path fifo = dir / "pipe";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0644), 0);
  const fs::path missing = dir / "missing";
  const std::vector<std::pair<std::string, std::function<std::vector<Diagnostic>(const fs::path&)>>> loaders{
      {"touch trace", [](const fs::path& p) { return load_touch_trace(p).diagnostics; }},
      {"volume scene", [](const fs::path& p) { return load_volume_scene_file(p, {}).diagnostics; }},
      {"NRRD volume", [](const fs::path& p) { return load_nrrd_volume(p).diagnostics; }},
  };
  for (const auto& [name, load] : loaders) {
    EXPECT_EQ(messages(load(missing)),
              std::vector<std::string>{missing.string() + ": error: cannot open: No such file or directory"})
        << name;
    EXPECT_EQ(messages(load(fifo)), std::vector<std::string>{fifo.string() + ": error: is not a regular file (a FIFO)"})
        << name;
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace vimg
