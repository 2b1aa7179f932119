#pragma once
// The report of `vimg study report` in its three forms (docs/studies.md "The report"): JSON for
// programs, a self-contained HTML page (inline CSS and SVG, nothing fetched: readable offline) and
// Markdown tables. All three lay out the same StudyReport; none computes anything.
//
// JSON: "study" is "matching", "location" or "both". For one kind the part's keys are at the top
// level; for both, under "matching" and "location", with the same keys:
//   matching: sets[] {name, images, comparison, trials, correct, accuracy, accuracy_ci95 [lo, hi],
//             chance, per_image[] {image, tp, fn, fp, tn, hit_rate, false_alarm_rate},
//             participants[] {participant, trials, correct, accuracy}, predicted?}, ttest (the two
//             sets; null unless exactly two), set_comparisons[] (every pair)
//   location: workspace_mm, chance_mm, metaphors[] {name, n, mean_mm, sd_mm, ci99_mm [lo, hi],
//             chance_mm}, ttest (the two metaphors; null unless two), metaphor_comparisons[],
//             participants[] {participant, metaphors[] {name, n, mean_mm}}
//   ttest and comparisons: {a, b, n_a, n_b, mean_a, mean_b, sd_a, sd_b, t, df, p, cohens_d}; a
//   statistic that is undefined (too few values, no variance) is null.
#include <string>

#include "study/report_model.hpp"

namespace vimg::study {

std::string report_json(const StudyReport& report);
std::string report_markdown(const StudyReport& report);
std::string report_html(const StudyReport& report);

}  // namespace vimg::study
