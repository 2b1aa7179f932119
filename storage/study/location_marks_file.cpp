#include "storage/study/location_marks_file.hpp"

#include "storage/csv_lines.hpp"
#include "storage/limits.hpp"
#include "storage/number_text.hpp"
#include "storage/load_file.hpp"

namespace vimg {
namespace {

constexpr std::string_view kHeader = "trial,time_s";

// A trial number: 1 to 9 decimal digits, nothing else.
std::optional<std::size_t> parse_trial(std::string_view cell) {
  if (cell.empty() || cell.size() > 9) return std::nullopt;
  std::size_t value = 0;
  for (const char c : cell) {
    if (c < '0' || c > '9') return std::nullopt;
    value = value * 10 + static_cast<std::size_t>(c - '0');
  }
  return value;
}

}  // namespace

MarkTimesResult parse_mark_times(std::string_view text, const std::string& file_name, std::size_t total_trials) {
  MarkTimesResult result;
  std::vector<double> times;
  DiagnosticList list(file_name);
  const std::string total_text = std::to_string(total_trials);
  CsvLines lines(text);
  const std::optional<std::string_view> header = lines.header();
  if (header && *header != kHeader) list.error(lines.line(), "the header must be 'trial,time_s'");
  while (!list.has_errors()) {
    const std::optional<std::string_view> next = lines.row();
    if (!next) break;
    const int line = lines.line();
    const std::string_view row = *next;
    const std::size_t comma = row.find(',');
    if (comma == std::string_view::npos || row.find(',', comma + 1) != std::string_view::npos) {
      list.error(line, "expected 2 columns (trial,time_s)");
      continue;
    }
    const std::string_view trial_cell = row.substr(0, comma), time_cell = row.substr(comma + 1);
    const std::optional<std::size_t> trial = parse_trial(trial_cell);
    if (!trial) {
      list.error(line, "trial '" + escape_input(trial_cell) + "' is not a whole number");
      continue;
    }
    if (times.size() == total_trials) {
      list.error(line, "more rows than the study's " + total_text + " trials");
      continue;
    }
    if (*trial != times.size() + 1) {
      list.error(line, "trial " + std::to_string(*trial) + " where trial " + std::to_string(times.size() + 1) +
                           " comes next (one row per trial, 1 to " + total_text + " in order)");
      continue;
    }
    const ParsedNumber parsed = parse_decimal(time_cell);
    if (const auto* why = std::get_if<std::string>(&parsed)) {
      list.error(line, "time_s '" + escape_input(time_cell) + "' " + *why);
      continue;
    }
    const double time_s = std::get<double>(parsed);
    if (!(time_s > 0.0) || time_s > kMaxProbePathDurationS) {
      list.error(line, "time_s " + format_decimal(time_s) + " is not in (0, " + format_decimal(kMaxProbePathDurationS) +
                           "] s (limit " + format_decimal(kMaxProbePathDurationS) + ")");
      continue;
    }
    times.push_back(time_s);
  }
  if (!list.has_errors()) {
    if (!header) {
      list.error(0, "empty file, expected the header 'trial,time_s'");
    } else if (times.size() < total_trials) {
      list.error(lines.line(), "no time for trial " + std::to_string(times.size() + 1) + ": the study has " + total_text +
                           " trials and each needs a row");
    }
  }
  if (!list.has_errors()) result.times_s = std::move(times);
  result.diagnostics = list.take();
  return result;
}

MarkTimesResult load_mark_times(const std::filesystem::path& file, std::size_t total_trials) {
  return load_file<MarkTimesResult>(file, kMaxCsvFileBytes, [&](std::string_view text, const std::string& name) {
    return parse_mark_times(text, name, total_trials);
  });
}

}  // namespace vimg
