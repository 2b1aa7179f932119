// Volumes written by teem (nrrdWrite into memory, storage/volume/teem_nrrd.hpp); the caller writes
// the bytes with write_file_atomically().
#include <stdexcept>

#include "storage/volume/nrrd.hpp"
#include "storage/volume/teem_nrrd.hpp"

namespace vimg {
namespace {

std::string write(const GridGeometry& g, const std::vector<float>& values, bool vector, NrrdEncoding encoding,
                  const std::string& content) {
  TeemNrrdPtr owner(nrrdNew());
  Nrrd& n = *owner;
  const std::size_t domain = vector ? 1 : 0;
  std::size_t sizes[4] = {3, 0, 0, 0};
  sizes[domain + 0] = static_cast<std::size_t>(g.size.nx);
  sizes[domain + 1] = static_cast<std::size_t>(g.size.ny);
  sizes[domain + 2] = static_cast<std::size_t>(g.size.nz);
  // teem only reads the samples; the struct is detached from them (nrrdNix) before it is freed.
  if (nrrdWrap_nva(&n, const_cast<float*>(values.data()), nrrdTypeFloat, vector ? 4 : 3, sizes) != 0 ||
      nrrdSpaceDimensionSet(&n, 3) != 0) {
    throw std::runtime_error("teem cannot describe the volume");
  }
  const double spacing_mm[3] = {g.spacing_m.x * 1e3, g.spacing_m.y * 1e3, g.spacing_m.z * 1e3};
  const double origin_mm[3] = {g.origin_m.x * 1e3, g.origin_m.y * 1e3, g.origin_m.z * 1e3};
  for (unsigned i = 0; i < 3; ++i) {
    NrrdAxisInfo& a = n.axis[domain + i];
    for (unsigned j = 0; j < 3; ++j) a.spaceDirection[j] = i == j ? spacing_mm[i] : 0.0;
    a.kind = nrrdKindDomain;
    n.spaceUnits[i] = airStrdup("mm");
  }
  if (vector) n.axis[0].kind = nrrdKindVector;
  nrrdSpaceOriginSet(&n, origin_mm);
  if (!content.empty()) n.content = airStrdup(content.c_str());
  nrrdCommentAdd(&n, "written by vibroimage");
  std::string out;
  const std::string error = teem_write(n, encoding == NrrdEncoding::gzip, out);
  n.data = nullptr;  // the samples belong to the grid
  if (!error.empty()) throw std::runtime_error("teem cannot write the volume: " + error);
  return out;
}

}  // namespace

std::string write_nrrd(const ScalarGrid& grid, NrrdEncoding encoding, const std::string& content) {
  return write(grid.geometry(), grid.values(), false, encoding, content);
}

std::string write_nrrd(const VectorGrid& grid, NrrdEncoding encoding, const std::string& content) {
  return write(grid.geometry(), grid.components(), true, encoding, content);
}

}  // namespace vimg
