#pragma once
// Scripted responses for a matching test without a person (`vimg-player --study ... --responses
// R.csv`): CSV with the header `trial,chosen`, one row per trial of the whole study, `chosen`
// naming an image of that trial's set by its file's stem. Rows may come in any order; every trial
// 1..N needs exactly one. Read like every file of the project (storage/read_file.hpp, at most
// kMaxCsvFileBytes); every problem is `FILE:LINE: error: ...` (or `FILE: error: ...` for the
// trials no row answers), and nothing runs unless the whole file is right.
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "storage/diagnostic.hpp"

namespace vimg {

struct ResponsesResult {
  // chosen[k - 1]: the image index (within trial k's set) chosen in trial k. Set only without errors.
  std::optional<std::vector<std::size_t>> chosen;
  std::vector<Diagnostic> diagnostics;
  bool ok() const { return chosen.has_value(); }
};

// `set_stems[s]`: the stems of set s's images, in file order; `trial_sets[k - 1]`: the set that
// trial k presents (the study's plan, study/trial_plan.hpp), so the study has trial_sets.size()
// trials.
ResponsesResult parse_responses(std::string_view text, const std::string& file_name,
                                const std::vector<std::vector<std::string>>& set_stems,
                                const std::vector<std::size_t>& trial_sets);
ResponsesResult load_responses(const std::filesystem::path& csv, const std::vector<std::vector<std::string>>& set_stems,
                               const std::vector<std::size_t>& trial_sets);

}  // namespace vimg
