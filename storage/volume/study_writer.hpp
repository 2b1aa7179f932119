#pragma once
// Writes the evaluation data set (primitives/volume/study_set.hpp) to a folder: feature.nrrd,
// flow.nrrd (gzip) and study.vscene.xml. Each file is written atomically.
#include <filesystem>
#include <optional>
#include <string>

#include "primitives/volume/study_set.hpp"

namespace vimg {

inline constexpr const char* kStudySceneFileName = "study.vscene.xml";

// Returns an error message, or nothing on success. Creates the folder if needed.
std::optional<std::string> write_study_set(const StudySet& set, const std::filesystem::path& dir);

}  // namespace vimg
