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

namespace vimg::study {

// Gives each set of `report` the first prediction that names all its images by stem, exactly once:
// its rows and columns restricted to the set's images and each row renormalised to 1 (a participant
// chooses within the set: Luce's choice axiom), the measured confusion, and their Pearson correlation
// over the off-diagonal cells. Returns a warning for each prediction that serves no set.
std::vector<Diagnostic> attach_predictions(MatchingReport& report, const std::vector<PredictedConfusion>& predictions);

}  // namespace vimg::study
