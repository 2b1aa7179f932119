// The scene layer over teem's NRRD reading (storage/volume/nrrd.hpp): the layouts a scene needs.
#include <array>
#include <cmath>
#include <set>

#include "storage/volume/nrrd.hpp"

namespace vimg {
namespace {

std::string in_quotes(std::string_view input) { return "'" + escape_input(input) + "'"; }

bool is_millimetres(const std::string& unit) { return unit.empty() || unit == "mm"; }

class SceneLayout {
 public:
  SceneLayout(const NrrdVolume& v, DiagnosticList& list) : v_(v), list_(list) {}

  std::optional<GridGeometry> geometry() {
    const std::size_t dim = v_.axes.size();
    if (dim != 3 && dim != 4) {
      error("dimension", "dimension must be 3 (scalar) or 4 (3-vector), got " + std::to_string(dim));
      return std::nullopt;
    }
    vector_ = dim == 4;
    if (vector_ && v_.axes[0].size != 3) {
      error("sizes", "a 4-dimensional volume must have 3 components on its first axis, got " + std::to_string(v_.axes[0].size));
      return std::nullopt;
    }
    if (vector_ && !v_.axes[0].kind.empty()) {
      static const std::set<std::string> vector_kinds = {"vector", "3-vector", "covariant-vector", "normal",
                                                         "3-color", "RGB-color", "list", "point"};
      if (!vector_kinds.count(v_.axes[0].kind)) {
        error("kinds", "the first axis of a vector volume must have a vector kind, got " + in_quotes(v_.axes[0].kind));
        return std::nullopt;
      }
    }
    if (v_.space_dimension != 0 && v_.space_dimension != 3) {
      error(v_.header.line_of("space") ? "space" : "space dimension",
            "the space must have 3 dimensions, got " + std::to_string(v_.space_dimension));
      return std::nullopt;
    }
    for (const auto& unit : v_.space_units) {
      if (!is_millimetres(unit)) {
        error("space units", "space units must be millimetres (\"mm\"), got " + in_quotes(unit));
        return std::nullopt;
      }
    }
    GridGeometry g;
    std::array<double, 3> spacing_mm{1.0, 1.0, 1.0};
    std::array<int, 3> size{};
    for (std::size_t i = 0; i < 3; ++i) {
      const NrrdAxis& a = v_.axes[i + (vector_ ? 1 : 0)];
      size[i] = static_cast<int>(a.size);
      if (!is_millimetres(a.units)) {
        error("units", "axis units must be millimetres (\"mm\"), got " + in_quotes(a.units));
        return std::nullopt;
      }
      if (std::isfinite(a.spacing)) {
        if (!(a.spacing > 0.0)) {
          error("spacings", "spacings must be positive, got " + std::to_string(a.spacing));
          return std::nullopt;
        }
        spacing_mm[i] = a.spacing;
      } else if (!a.space_direction.empty()) {
        for (std::size_t j = 0; j < 3; ++j) {
          if (j != i && a.space_direction[j] != 0.0) {
            error("space directions", "space directions must be axis-aligned (a diagonal matrix)");
            return std::nullopt;
          }
        }
        if (!(a.space_direction[i] > 0.0)) {
          error("space directions", "space directions must be positive along each axis");
          return std::nullopt;
        }
        spacing_mm[i] = a.space_direction[i];
      }
    }
    if (vector_ && v_.axes[0].space_direction.size() != 0) {
      error("space directions", "the vector axis must have space direction 'none'");
      return std::nullopt;
    }
    g.size = {size[0], size[1], size[2]};
    g.spacing_m = Vec3{spacing_mm[0], spacing_mm[1], spacing_mm[2]} * 1e-3;
    if (v_.space_origin.size() == 3 && std::isfinite(v_.space_origin[0])) {
      g.origin_m = Vec3{v_.space_origin[0], v_.space_origin[1], v_.space_origin[2]} * 1e-3;
    }
    return g;
  }

  bool vector() const { return vector_; }

 private:
  void error(std::string_view field, const std::string& message) { list_.error(v_.header.line_of(field), message); }

  const NrrdVolume& v_;
  DiagnosticList& list_;
  bool vector_ = false;
};

}  // namespace

NrrdLoadResult parse_nrrd(std::string_view bytes, const std::string& file_name, const NrrdReadOptions& options) {
  DiagnosticList list(file_name);
  NrrdLoadResult result;
  std::optional<NrrdVolume> volume = read_nrrd_volume(bytes, options, list);
  if (volume) {
    SceneLayout layout(*volume, list);
    const std::optional<GridGeometry> geometry = layout.geometry();
    if (geometry) {
      for (std::size_t i = 0; i < volume->values.size(); ++i) {
        if (!std::isfinite(volume->values[i])) {
          list.error(volume->header.data_line, "sample " + std::to_string(i) + " is not a finite float");
          break;
        }
      }
    }
    if (geometry && !list.has_errors()) {
      if (layout.vector()) result.vector.emplace(*geometry, std::move(volume->values));
      else result.scalar.emplace(*geometry, std::move(volume->values));
    }
  }
  result.diagnostics = list.take();
  return result;
}

NrrdLoadResult load_nrrd_file(const std::filesystem::path& path, const NamedFileOptions& named) {
  NrrdFile file = read_nrrd_file(path, named);
  if (!file.bytes) {
    NrrdLoadResult r;
    r.diagnostics = std::move(file.diagnostics);
    return r;
  }
  return parse_nrrd(*file.bytes, path.string(), file.options);
}

}  // namespace vimg
