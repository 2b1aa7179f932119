#include "storage/volume/study_writer.hpp"

#include <system_error>

#include "storage/atomic_file.hpp"
#include "storage/volume/nrrd.hpp"
#include "storage/volume/volume_scene_io.hpp"

namespace vimg {

std::optional<std::string> write_study_set(const StudySet& set, const std::filesystem::path& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) return dir.string() + ": cannot create folder: " + ec.message();
  if (auto e = write_file_atomically(dir / "feature.nrrd", write_nrrd(set.feature, NrrdEncoding::gzip,
                                                                      "signed distance to the feature plane (mm)"))) {
    return e;
  }
  if (auto e = write_file_atomically(dir / "flow.nrrd", write_nrrd(set.flow, NrrdEncoding::gzip, "flow direction"))) {
    return e;
  }
  return write_file_atomically(dir / kStudySceneFileName, write_volume_scene_xml(set.scene));
}

}  // namespace vimg
