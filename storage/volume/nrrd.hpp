#pragma once
// NRRD volumes (teem's "nearly raw raster data"), the scientific-visualization format for
// scalar and vector grids. A strict reader of what the volume backend needs:
//   - magic NRRD0001..NRRD0005, then `field: value` lines, `#` comments and `key:=value` pairs,
//     ended by an empty line and followed by the attached data;
//   - dimension 3 (a scalar grid) or 4 with a first axis of size 3 (a 3-vector grid);
//   - types int8..uint64, float, double (converted to float); raw, gzip and ascii encodings;
//   - axis-aligned geometry from `spacings` or a diagonal `space directions`, `space origin`;
//     positions in millimetres.
// Anything else (detached data, unknown fields, skewed axes, short or long data) is an error
// naming the file and, for header problems, the line.
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "primitives/volume/scalar_grid.hpp"
#include "primitives/volume/vector_grid.hpp"
#include "storage/diagnostic.hpp"
#include "storage/limits.hpp"

namespace vimg {

struct NrrdLoadResult {
  std::optional<ScalarGrid> scalar;  // set for a valid scalar volume
  std::optional<VectorGrid> vector;  // set for a valid 3-vector volume
  std::vector<Diagnostic> diagnostics;
  bool ok() const { return scalar.has_value() || vector.has_value(); }
};

// Parses a whole NRRD file held in memory; `file_name` is used in messages only.
NrrdLoadResult parse_nrrd(std::string_view bytes, const std::string& file_name);
NrrdLoadResult load_nrrd_file(const std::filesystem::path& path);

enum class NrrdEncoding { raw, gzip };

// A NRRD0004 file of float samples, little-endian, with spacings and origin in mm.
std::string write_nrrd(const ScalarGrid& grid, NrrdEncoding encoding, const std::string& content = {});
std::string write_nrrd(const VectorGrid& grid, NrrdEncoding encoding, const std::string& content = {});

}  // namespace vimg
