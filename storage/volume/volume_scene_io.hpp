#pragma once
// Volume scene files (XML, docs/volume-data.md) and loading a scene with its NRRD data.
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "primitives/volume/scalar_grid.hpp"
#include "primitives/volume/vector_grid.hpp"
#include "primitives/volume/volume_scene.hpp"
#include "storage/diagnostic.hpp"

namespace vimg {

struct VolumeSceneParseResult {
  std::optional<VolumeScene> scene;  // set only when there is no error
  std::vector<Diagnostic> diagnostics;
  bool ok() const { return scene.has_value(); }
};

VolumeSceneParseResult parse_volume_scene_xml(std::string_view xml, const std::string& file_name);

// The canonical XML text of a scene; parse_volume_scene_xml reads it back to an equal scene.
std::string write_volume_scene_xml(const VolumeScene& scene);

// A scene with every data file it names, loaded and checked.
struct LoadedVolumeScene {
  VolumeScene scene;
  std::map<std::string, std::shared_ptr<const ScalarGrid>> scalars;
  std::map<std::string, std::shared_ptr<const VectorGrid>> vectors;
};

struct VolumeSceneLoadResult {
  std::optional<LoadedVolumeScene> loaded;
  std::vector<Diagnostic> diagnostics;
  bool ok() const { return loaded.has_value(); }
};

struct VolumeSceneLoadOptions {
  // Data files must be in the scene's folder or below it; true lets `file=` lead anywhere (an
  // absolute path, `..`), for the user's explicit request only. Either way a data file is a regular
  // file (never a symbolic link, FIFO or device) within kMaxVolumeFileBytes (storage/named_file.hpp).
  bool allow_files_outside_scene_folder = false;
};

// Reads the scene (at most kMaxSceneFileBytes), then every NRRD file it names (relative to the
// scene's folder), checking that each is the declared kind (scalar or vector).
VolumeSceneLoadResult load_volume_scene_file(const std::filesystem::path& path,
                                             const VolumeSceneLoadOptions& options = {});

}  // namespace vimg
