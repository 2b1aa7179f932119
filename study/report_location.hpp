#pragma once
// The location study's part of the report (volume paper, section 5; docs/studies.md): per metaphor
// n, mean error, SD and the 99 % t interval of the mean, chance for the trials' targets, Welch's
// t-test with Cohen's d on the errors between metaphors, and each participant's mean errors.
#include <vector>

#include "storage/study/trial_table.hpp"
#include "study/report_chance.hpp"
#include "study/report_model.hpp"

namespace vimg::study {

LocationReport make_location_report(const std::vector<LocationTrial>& trials,
                                    const Workspace& workspace = study_workspace());

}  // namespace vimg::study
