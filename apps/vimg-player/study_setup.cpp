#include "apps/vimg-player/study_setup.hpp"

#include <utility>

#include "storage/image_io.hpp"
#include "study/matching_row.hpp"

namespace vimg::player_app {

std::vector<std::size_t> StudyMaterial::images_per_set() const {
  std::vector<std::size_t> counts;
  for (const auto& set : images) counts.push_back(set.size());
  return counts;
}

StudyMaterialResult load_study_material(const std::filesystem::path& study_file, const std::string& participant) {
  StudyMaterialResult result;
  auto loaded = load_matching_study(study_file);
  result.diagnostics = std::move(loaded.diagnostics);
  if (!loaded.ok()) return result;
  StudyMaterial material;
  material.study = std::move(*loaded.study);
  bool images_ok = true;
  for (const auto& set : material.study.sets) {
    auto& images = material.images.emplace_back();
    auto& stems = material.stems.emplace_back();
    for (const auto& path : set.images) {
      LoadResult image = load_image_file(path);
      result.diagnostics.insert(result.diagnostics.end(), image.diagnostics.begin(), image.diagnostics.end());
      stems.push_back(study_image_name(path));
      if (!image.ok()) {
        images_ok = false;
        continue;
      }
      images.push_back(std::move(*image.image));
    }
  }
  if (!images_ok) return result;
  material.plan = study::plan_matching_trials(material.study, participant);
  result.material = std::move(material);
  return result;
}

MatchingTrial trial_row(const StudyMaterial& material, const std::string& participant, const study::StudyTrialResult& result,
                        std::string time_utc) {
  return study::matching_trial_row(material.study, material.stems, participant, result, std::move(time_utc));
}

std::string trial_status_line(const StudyMaterial& material, const study::StudyTrialResult& result) {
  return "vimg-player: trial " + std::to_string(result.trial) + " of " + std::to_string(material.plan.size()) +
         " (set " + material.set_name(result.set) + "): presented " + material.stems[result.set][result.presented] +
         ", chosen " + material.stems[result.set][result.chosen];
}

}  // namespace vimg::player_app
