#pragma once
// The predicted confusion that `vimg compare` writes (read by storage/study/predicted_confusion.hpp)
// set beside the measured one for `vimg study report --predicted` (docs/studies.md "Predicted
// against measured").
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "storage/diagnostic.hpp"
#include "storage/study/predicted_confusion.hpp"
#include "storage/limits.hpp"
#include "study/report_model.hpp"
#include "study/separate_search.hpp"

namespace vimg::study {

// Gives each set of `report` the first prediction that names all its images by stem, exactly once:
// its rows and columns restricted to the set's images and each row renormalised to 1 (a participant
// chooses within the set; exact for a prediction of the set's own images, an approximation for a
// larger one: each image's cell depends on the other members and the context noise on the set's
// range, docs/identification.md), the measured confusion, and their Pearson correlation over the
// off-diagonal cells.
// Returns a warning for each prediction that serves no set.
std::vector<Diagnostic> attach_predictions(MatchingReport& report, const std::vector<PredictedConfusion>& predictions);

// For a set whose prediction identifies an image less than kIdentifiedTarget (`vimg separate`'s
// default target) of the time: "set 'A': the prediction identifies 'x' only 67 % of the time (below 90 %); `vimg separate` on the
// set's images proposes which tactile parameters to change, and how far (docs/separate.md)", at the
// prediction's file; nothing when the set has no prediction or every image reaches the target.
std::optional<Diagnostic> low_identification_warning(const SetReport& set);

}  // namespace vimg::study
