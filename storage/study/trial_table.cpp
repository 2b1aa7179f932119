// Reading whole trial files (storage/study/trial_table.hpp): the header, then one row per line,
// with the torn-last-line rule of storage/study/trial_text.hpp.
#include "storage/study/trial_table.hpp"

#include <algorithm>
#include <map>
#include <optional>

#include "storage/csv_lines.hpp"
#include "storage/limits.hpp"
#include "storage/load_file.hpp"
#include "storage/read_file.hpp"
#include "storage/study/trial_text.hpp"

namespace vimg {
namespace trial_text {
namespace {

void split_cells(std::string_view line, std::vector<std::string_view>& cells) {
  cells.clear();
  std::size_t start = 0;
  for (;;) {
    const std::size_t comma = line.find(',', start);
    if (comma == std::string_view::npos) {
      cells.push_back(line.substr(start));
      return;
    }
    cells.push_back(line.substr(start, comma - start));
    start = comma + 1;
  }
}

struct Schema {
  const std::vector<std::string>& header;
  const char* kind;        // "matching", "location"
  const std::vector<std::string>& other_header;
  const char* other_kind;
};

template <class Row>
TrialText<Row> parse_table(std::string_view text, const std::string& file_name, const Schema& schema) {
  TrialText<Row> out;
  DiagnosticList list(file_name);
  const std::string header = header_line(schema.header);
  const auto finish = [&]() {
    out.table.diagnostics = list.take();
    if (!out.table.ok()) out.table.rows.clear();
    return std::move(out);
  };

  std::size_t end = text.find('\n');
  const bool header_ends = end != std::string_view::npos;
  if (!header_ends) end = text.size();
  std::string_view first = text.substr(0, end);
  if (first.ends_with('\r')) first.remove_suffix(1);
  if (first != header) {
    if (!header_ends && std::string_view(header).starts_with(first)) {
      // Nothing or part of the header: the file was cut while it was begun. No trials.
      list.warning(1, text.empty() ? "the file is empty: no header, no trials"
                                   : "the header line is cut short (the file was cut while it was begun): no trials");
    } else if (first == header_line(schema.other_header)) {
      list.error(1, std::string("this is a ") + schema.other_kind + " trial file, expected a " + schema.kind +
                        " trial file (header '" + header + "')");
    } else {
      list.error(1, "expected the header '" + header + "'");
    }
    return finish();
  }
  out.complete_bytes = header_ends ? end + 1 : end;
  out.missing_line_break = !header_ends;

  // The rows are counted before any is read: a file over the limit costs one pass of memchr.
  const std::string_view rest = text.substr(out.complete_bytes);
  const std::size_t rows = static_cast<std::size_t>(std::count(rest.begin(), rest.end(), '\n')) +
                           (rest.empty() || rest.back() == '\n' ? 0 : 1);
  if (rows > kMaxTrialRows) {
    list.error(static_cast<int>(kMaxTrialRows) + 2, csv_row_limit_problem(kMaxTrialRows));
    return finish();
  }
  std::map<std::string, std::pair<int, int>, std::less<>> last_trial;  // participant -> trial, line
  int line_no = 1;
  std::size_t pos = out.complete_bytes;
  std::vector<std::string_view> cells;
  while (pos < text.size()) {
    end = text.find('\n', pos);
    const bool ends = end != std::string_view::npos;
    if (!ends) end = text.size();
    std::string_view line = text.substr(pos, end - pos);
    if (line.ends_with('\r')) line.remove_suffix(1);
    pos = end + 1;
    ++line_no;
    // A last line without its line break is checked on its own: kept when it is a whole row, else
    // left out with a warning.
    std::optional<DiagnosticList> torn;
    if (!ends) torn.emplace(file_name);
    DiagnosticList& into = ends ? list : *torn;
    Row row;
    bool ok = false;
    split_cells(line, cells);
    if (line.empty()) {
      into.error(line_no, "empty line (every line after the header is one trial)");
    } else if (cells.size() != schema.header.size()) {
      into.error(line_no, "expected " + std::to_string(schema.header.size()) + " cells (" + header + "), found " +
                              std::to_string(cells.size()));
    } else {
      ok = parse_row(cells, line_no, into, row);
    }
    if (!ends && !ok) {
      list.warning(line_no, "the last line is cut short (no line break): the trial under way when the file was cut, left out");
      break;
    }
    if (!ok) continue;
    const auto [it, inserted] = last_trial.try_emplace(row.participant, row.trial, line_no);
    if (!inserted) {
      if (row.trial <= it->second.first) {
        list.error(line_no, "trial " + std::to_string(row.trial) + " of participant '" + row.participant + "' follows trial " +
                                std::to_string(it->second.first) + " (line " + std::to_string(it->second.second) +
                                "): trial numbers must increase");
        continue;
      }
      it->second = {row.trial, line_no};
    }
    out.table.rows.push_back(std::move(row));
    out.complete_bytes = ends ? end + 1 : end;
    out.missing_line_break = !ends;
  }
  return finish();
}

template <class Row>
TrialTableResult<Row> read_file(const std::filesystem::path& csv, TrialText<Row> (*parse)(std::string_view, const std::string&)) {
  return load_file<TrialTableResult<Row>>(csv, kMaxTrialFileBytes, [parse](std::string_view text, const std::string& name) {
    return parse(text, name).table;
  });
}

}  // namespace

TrialText<MatchingTrial> parse_matching(std::string_view text, const std::string& file_name) {
  return parse_table<MatchingTrial>(text, file_name, {kMatchingTrialHeader, "matching", kLocationTrialHeader, "location"});
}

TrialText<LocationTrial> parse_location(std::string_view text, const std::string& file_name) {
  return parse_table<LocationTrial>(text, file_name, {kLocationTrialHeader, "location", kMatchingTrialHeader, "matching"});
}

}  // namespace trial_text

TrialTableResult<MatchingTrial> parse_matching_trials(std::string_view text, const std::string& file_name) {
  return trial_text::parse_matching(text, file_name).table;
}

TrialTableResult<LocationTrial> parse_location_trials(std::string_view text, const std::string& file_name) {
  return trial_text::parse_location(text, file_name).table;
}

TrialTableResult<MatchingTrial> read_matching_trials(const std::filesystem::path& csv) {
  return trial_text::read_file<MatchingTrial>(csv, &trial_text::parse_matching);
}

TrialTableResult<LocationTrial> read_location_trials(const std::filesystem::path& csv) {
  return trial_text::read_file<LocationTrial>(csv, &trial_text::parse_location);
}

TrialFileKind trial_file_kind(const std::filesystem::path& csv) {
  const FileReadResult text = read_regular_file(csv, kMaxTrialFileBytes);
  if (!text.bytes) return TrialFileKind::unknown;
  std::string_view first = std::string_view(*text.bytes).substr(0, text.bytes->find('\n'));
  if (first.ends_with('\r')) first.remove_suffix(1);
  if (first == trial_text::header_line(kMatchingTrialHeader)) return TrialFileKind::matching;
  if (first == trial_text::header_line(kLocationTrialHeader)) return TrialFileKind::location;
  return TrialFileKind::unknown;
}

}  // namespace vimg
