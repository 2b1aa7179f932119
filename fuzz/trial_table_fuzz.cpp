// Fuzzes both trial-file readers (storage/study/trial_table.hpp) on the same bytes: any input gives
// located errors or rows within the rules of docs/format-studies.md "Trial files", never a crash; every
// message is printable and bounded; and the rows read, written again with to_cells, read back to
// exactly the same cells (the report and the log agree on every file).
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <map>
#include <string>
#include <string_view>

#include "fuzz/check_messages.hpp"
#include "storage/limits.hpp"
#include "storage/study/trial_table.hpp"

namespace {

std::string line_of(const std::vector<std::string>& cells) {
  std::string line;
  for (std::size_t i = 0; i < cells.size(); ++i) line += (i ? "," : "") + cells[i];
  return line + "\n";
}

template <class Row>
void check(const vimg::TrialTableResult<Row>& r, const std::vector<std::string>& header,
           vimg::TrialTableResult<Row> (*parse)(std::string_view, const std::string&)) {
  vimg::fuzz::check_messages(r.diagnostics);
  if (!r.ok()) {
    if (!r.rows.empty()) std::abort();  // no rows from a file with an error
    return;
  }
  if (r.rows.size() > vimg::kMaxTrialRows) std::abort();
  std::map<std::string, int> last;
  std::string again = line_of(header);
  for (const Row& row : r.rows) {
    if (row.trial < 1 || static_cast<std::size_t>(row.trial) > vimg::kMaxStudyTrials) std::abort();
    int& previous = last[row.participant];
    if (row.trial <= previous) std::abort();  // trial numbers increase per participant
    previous = row.trial;
    const std::vector<std::string> cells = vimg::to_cells(row);
    if (cells.size() != header.size()) std::abort();
    again += line_of(cells);
  }
  const auto second = parse(again, "again.csv");
  if (!second.ok() || !second.diagnostics.empty() || second.rows.size() != r.rows.size()) std::abort();
  for (std::size_t i = 0; i < r.rows.size(); ++i) {
    if (vimg::to_cells(second.rows[i]) != vimg::to_cells(r.rows[i])) std::abort();
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  check(vimg::parse_matching_trials(text, "fuzz.csv"), vimg::kMatchingTrialHeader, &vimg::parse_matching_trials);
  check(vimg::parse_location_trials(text, "fuzz.csv"), vimg::kLocationTrialHeader, &vimg::parse_location_trials);
  return 0;
}
