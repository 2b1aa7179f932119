#include "study/matching_row.hpp"

#include <utility>

namespace vimg::study {

MatchingTrial matching_trial_row(const MatchingStudy& study, const std::vector<std::vector<std::string>>& stems,
                                 const std::string& participant, const StudyTrialResult& result, std::string time_utc) {
  MatchingTrial row;
  row.participant = participant;
  row.set = study.sets[result.set].name;
  row.trial = static_cast<int>(result.trial);
  row.presented = stems[result.set][result.presented];
  row.chosen = stems[result.set][result.chosen];
  row.correct = result.presented == result.chosen;
  row.rub_s = result.rub_s;
  row.response_s = result.response_s;
  row.path_mm = result.path_mm;
  row.time_utc = std::move(time_utc);
  return row;
}

std::vector<std::vector<std::string>> matching_study_stems(const MatchingStudy& study) {
  std::vector<std::vector<std::string>> stems;
  for (const auto& set : study.sets) {
    auto& names = stems.emplace_back();
    for (const auto& image : set.images) names.push_back(study_image_name(image));
  }
  return stems;
}

}  // namespace vimg::study
