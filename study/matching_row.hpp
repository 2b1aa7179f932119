#pragma once
// The one place a matching trial's result becomes a trial-file row (storage/study/trial_table.hpp),
// for every runner: vimg-player writes it on the device, `vimg serve --study` when a page answers.
#include <string>
#include <vector>

#include "storage/study/study_file.hpp"
#include "storage/study/trial_table.hpp"
#include "study/study_flow.hpp"

namespace vimg::study {

// `stems[s][i]`: the name of image i of set s (study_image_name). correct = presented == chosen.
MatchingTrial matching_trial_row(const MatchingStudy& study, const std::vector<std::vector<std::string>>& stems,
                                 const std::string& participant, const StudyTrialResult& result, std::string time_utc);

// Every set's image stems, in file order.
std::vector<std::vector<std::string>> matching_study_stems(const MatchingStudy& study);

}  // namespace vimg::study
