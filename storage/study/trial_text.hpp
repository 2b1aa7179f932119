#pragma once
// Internal to storage/study (trial_table.cpp, trial_rows.cpp, trial_log.cpp): a trial file read
// line by line, with what the trial log needs beyond the rows: where the last complete line ends.
//
// A trial file is appended one whole line at a time (storage/study/trial_log.hpp), so the only
// damage a crash can leave is a last line without its line break. Such a line is part of the table
// when it is a complete, valid row (only the line break was lost) and is otherwise left out with a
// warning (the trial under way when the file was cut). Every other problem is an error.
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "storage/diagnostic.hpp"
#include "storage/study/trial_table.hpp"

namespace vimg::trial_text {

template <class Row>
struct TrialText {
  TrialTableResult<Row> table;
  std::size_t complete_bytes = 0;  // the header and the rows kept, from the file's start
  bool missing_line_break = false;  // the last line kept ends at complete_bytes without its line break
};

TrialText<MatchingTrial> parse_matching(std::string_view text, const std::string& file_name);
TrialText<LocationTrial> parse_location(std::string_view text, const std::string& file_name);

// The cells of one row, parsed and checked (each problem reported at `line`); false when any.
bool parse_row(const std::vector<std::string_view>& cells, int line, DiagnosticList& list, MatchingTrial& row);
bool parse_row(const std::vector<std::string_view>& cells, int line, DiagnosticList& list, LocationTrial& row);

// The header as a line (without its line break).
std::string header_line(const std::vector<std::string>& header);

}  // namespace vimg::trial_text
