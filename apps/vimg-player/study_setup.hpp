#pragma once
// What a matching test needs before its first trial, read and checked at once (nothing is shown
// until all of it is right): the study file (storage/study/study_file.hpp), every image of every set
// (storage/image_io.hpp), their stems (the names in the trial file) and the participant's seeded
// trial order (study/trial_plan.hpp). And the one place a trial's result becomes a trial-file row.
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "study/study_flow.hpp"
#include "primitives/image.hpp"
#include "storage/diagnostic.hpp"
#include "storage/study/study_file.hpp"
#include "storage/study/trial_table.hpp"
#include "study/trial_plan.hpp"

namespace vimg::player_app {

struct StudyMaterial {
  MatchingStudy study;
  std::vector<std::vector<Image>> images;        // [set][image], in file order
  std::vector<std::vector<std::string>> stems;   // the same, named by file stem
  std::vector<study::MatchingTrialPlan> plan;    // trial k is plan[k - 1]

  std::vector<std::size_t> images_per_set() const;
  const std::string& set_name(std::size_t set) const { return study.sets[set].name; }
};

struct StudyMaterialResult {
  std::optional<StudyMaterial> material;  // set only without errors
  std::vector<Diagnostic> diagnostics;    // the study file's, then each image's (warnings too)
};

StudyMaterialResult load_study_material(const std::filesystem::path& study_file, const std::string& participant);

// The trial-file row of a result (correct = presented == chosen).
MatchingTrial trial_row(const StudyMaterial& material, const std::string& participant, const study::StudyTrialResult& result,
                        std::string time_utc);

// The line printed on stdout once a trial's row is on disk (tests wait on it):
// "vimg-player: trial 3 of 40 (set complexity): presented dot, chosen line".
std::string trial_status_line(const StudyMaterial& material, const study::StudyTrialResult& result);

}  // namespace vimg::player_app
