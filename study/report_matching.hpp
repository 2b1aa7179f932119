#pragma once
// The matching test's part of the report (primitives paper, section 3; docs/studies.md): per image
// set the comparison matrix, per image TP/FN/FP/TN with hit and false-alarm rates, the accuracy with
// its Wilson interval against chance, the accuracy per participant, and Welch's t-test with Cohen's d
// on per-participant accuracies between sets.
#include <vector>

#include "storage/study/trial_table.hpp"
#include "study/report_model.hpp"

namespace vimg::study {

// Trials of any number of participants and files; every trial counts once (the caller refuses a
// participant's trial given twice). Sets keep the order in which the trials first name them.
MatchingReport make_matching_report(const std::vector<MatchingTrial>& trials);

}  // namespace vimg::study
