#include "storage/study/scripted_responses.hpp"

#include <charconv>

#include "storage/csv_lines.hpp"
#include "storage/diagnostic.hpp"
#include "storage/limits.hpp"
#include "storage/load_file.hpp"
#include "storage/text_trim.hpp"

namespace vimg {

namespace {

std::vector<std::string_view> split_cells(std::string_view line) {
  std::vector<std::string_view> cells;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    cells.push_back(trim_blanks(line.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start)));
    if (comma == std::string_view::npos) return cells;
    start = comma + 1;
  }
}

// "5, 9, 12" and "and N more" after the first few.
std::string missing_list(const std::vector<std::size_t>& trials) {
  constexpr std::size_t kShown = 8;
  std::string text;
  for (std::size_t i = 0; i < trials.size() && i < kShown; ++i) text += (i ? ", " : "") + std::to_string(trials[i]);
  if (trials.size() > kShown) text += " and " + std::to_string(trials.size() - kShown) + " more";
  return text;
}

}  // namespace

ResponsesResult parse_responses(std::string_view text, const std::string& file_name,
                                const std::vector<std::vector<std::string>>& set_stems,
                                const std::vector<std::size_t>& trial_sets) {
  DiagnosticList problems(file_name, DiagnosticList::Order::by_line);
  const std::size_t total = trial_sets.size();
  std::vector<std::size_t> chosen(total, 0);
  std::vector<int> answered_at(total, 0);  // the line that answered each trial, 0: none yet
  CsvLines lines(text, {.trim_blanks = true, .comments = false});
  const std::optional<std::string_view> header = lines.header();
  bool header_ok = false;
  if (header) {
    const auto cells = split_cells(*header);
    header_ok = cells.size() == 2 && cells[0] == "trial" && cells[1] == "chosen";
    // What follows cannot be read without it.
    if (!header_ok) problems.error(lines.line(), "the header must be 'trial,chosen', not '" + escape_input(*header) + "'");
  }
  while (header_ok) {
    const std::optional<std::string_view> line = lines.row();
    if (!line) break;
    const int line_number = lines.line();
    const auto cells = split_cells(*line);
    if (cells.size() != 2) {
      problems.error(line_number, "expected 2 cells (trial,chosen), found " + std::to_string(cells.size()));
      continue;
    }
    std::size_t trial = 0;
    const auto parsed = std::from_chars(cells[0].data(), cells[0].data() + cells[0].size(), trial);
    if (cells[0].empty() || parsed.ec != std::errc() || parsed.ptr != cells[0].data() + cells[0].size() ||
        trial < 1 || trial > total) {
      problems.error(line_number, "trial '" + escape_input(cells[0]) + "' is not a trial number of this study (1.." +
                                      std::to_string(total) + ")");
      continue;
    }
    if (answered_at[trial - 1] != 0) {
      problems.error(line_number, "trial " + std::to_string(trial) + " is answered twice (first at line " +
                                      std::to_string(answered_at[trial - 1]) + ")");
      continue;
    }
    const auto& stems = set_stems.at(trial_sets[trial - 1]);
    std::size_t image = 0;
    while (image < stems.size() && stems[image] != cells[1]) ++image;
    if (image == stems.size()) {
      problems.error(line_number, "trial " + std::to_string(trial) + ": '" + escape_input(cells[1]) +
                                      "' is not an image of its set (" + listed_names(stems) + ")");
      continue;
    }
    answered_at[trial - 1] = line_number;
    chosen[trial - 1] = image;
  }
  if (!header) problems.error(lines.line() > 0 ? 1 : 0, "empty file: expected the header 'trial,chosen'");
  ResponsesResult result;
  if (!problems.has_errors()) {
    std::vector<std::size_t> missing;
    for (std::size_t k = 0; k < total; ++k) {
      if (answered_at[k] == 0) missing.push_back(k + 1);
    }
    if (!missing.empty()) {
      problems.error(0, "no response for trial " + missing_list(missing) + ": every trial of the study (1.." +
                            std::to_string(total) + ") needs one");
    }
  }
  if (!problems.has_errors()) result.chosen = std::move(chosen);
  result.diagnostics = problems.take();
  return result;
}

ResponsesResult load_responses(const std::filesystem::path& csv, const std::vector<std::vector<std::string>>& set_stems,
                               const std::vector<std::size_t>& trial_sets) {
  return load_file<ResponsesResult>(csv, kMaxCsvFileBytes, [&](std::string_view text, const std::string& name) {
    return parse_responses(text, name, set_stems, trial_sets);
  });
}

}  // namespace vimg
