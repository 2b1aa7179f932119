#pragma once
// NRRD volumes as a scene needs them: a scalar grid or a 3-vector grid. The file is read by teem
// through storage/volume/nrrd_volume.hpp (every type, endianness, raw/gzip/bzip2/ASCII/hex
// encoding, attached or detached data, with vibroimage's limits and confined data files); on top
// of it this layer asks for the layout a scene needs, naming the field when it is not met:
//   - dimension 3 (a scalar grid), or 4 with a first axis of 3 components (a 3-vector grid, whose
//     first axis has a vector kind when it has a kind);
//   - axis-aligned geometry: `spacings`, or a diagonal `space directions` with positive entries,
//     in a 3-dimensional space; `space origin`; lengths in millimetres (`space units` and axis
//     `units` are "mm" or absent);
//   - finite samples, converted to float.
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "primitives/volume/scalar_grid.hpp"
#include "primitives/volume/vector_grid.hpp"
#include "storage/diagnostic.hpp"
#include "storage/limits.hpp"
#include "storage/volume/nrrd_volume.hpp"

namespace vimg {

struct NrrdLoadResult {
  std::optional<ScalarGrid> scalar;  // set for a valid scalar volume
  std::optional<VectorGrid> vector;  // set for a valid 3-vector volume
  std::vector<Diagnostic> diagnostics;
  bool ok() const { return scalar.has_value() || vector.has_value(); }
};

// Parses a whole NRRD file held in memory; `file_name` is used in messages only. A detached
// header needs `options.folder` (load_nrrd_file sets it to the header's folder).
NrrdLoadResult parse_nrrd(std::string_view bytes, const std::string& file_name, const NrrdReadOptions& options = {});
NrrdLoadResult load_nrrd_file(const std::filesystem::path& path, const NamedFileOptions& named = {});

enum class NrrdEncoding { raw, gzip };

// A NRRD file of float samples written by teem: a 3-dimensional space with space directions,
// origin and units in mm; the vector grid's first axis has kind "vector".
std::string write_nrrd(const ScalarGrid& grid, NrrdEncoding encoding, const std::string& content = {});
std::string write_nrrd(const VectorGrid& grid, NrrdEncoding encoding, const std::string& content = {});

}  // namespace vimg
