// The rows of the two trial files: their headers, to_cells and the check of one row's cells
// (storage/study/trial_table.hpp, trial_text.hpp).
#include <charconv>
#include <cmath>
#include <system_error>

#include "storage/limits.hpp"
#include "storage/number_text.hpp"
#include "storage/study/study_names.hpp"
#include "storage/study/trial_log.hpp"
#include "storage/study/trial_text.hpp"

namespace vimg {

const std::vector<std::string> kMatchingTrialHeader{"participant", "set",     "trial",      "presented", "chosen",
                                                    "correct",     "rub_s",   "response_s", "path_mm",   "time_utc"};
const std::vector<std::string> kLocationTrialHeader{"participant", "trial",     "metaphor",  "seed",
                                                    "target_x_mm", "target_z_mm", "mark_x_mm", "mark_y_mm",
                                                    "mark_z_mm",   "error_mm",  "explore_s", "time_utc"};

std::vector<std::string> to_cells(const MatchingTrial& t) {
  return {t.participant,          t.set,        std::to_string(t.trial),        t.presented,
          t.chosen,               t.correct ? "1" : "0", format_decimal(t.rub_s), format_decimal(t.response_s),
          format_decimal(t.path_mm), t.time_utc};
}

std::vector<std::string> to_cells(const LocationTrial& t) {
  return {t.participant,
          std::to_string(t.trial),
          std::string(location_metaphor_name(t.metaphor)),
          std::to_string(t.seed),
          format_decimal(t.target_x_mm),
          format_decimal(t.target_z_mm),
          format_decimal(t.mark_x_mm),
          format_decimal(t.mark_y_mm),
          format_decimal(t.mark_z_mm),
          format_decimal(t.error_mm),
          format_decimal(t.explore_s),
          t.time_utc};
}

namespace trial_text {
namespace {

std::string q(std::string_view cell) { return "'" + escape_input(cell) + "'"; }

// One row's checks, each reported at the row's line with the column's name.
class Cells {
 public:
  Cells(const std::vector<std::string_view>& cells, int line, DiagnosticList& list) : cells_(cells), line_(line), list_(list) {}
  bool ok() const { return ok_; }

  void bad(std::string_view column, std::size_t i, std::string_view problem) {
    ok_ = false;
    list_.error(line_, std::string(column) + " " + q(cells_[i]) + " " + std::string(problem));
  }

  void participant(std::size_t i, std::string& out) {
    if (!valid_participant_id(cells_[i])) bad("participant", i, "is not a participant ID (1 to 64 of A-Z a-z 0-9 _ -)");
    else out = cells_[i];
  }
  void name(std::string_view column, std::size_t i, std::string& out) {
    if (const auto problem = study_name_problem(cells_[i])) bad(column, i, *problem);
    else out = cells_[i];
  }
  void trial(std::size_t i, int& out) {
    const std::string_view c = cells_[i];
    int v = 0;
    const auto [ptr, ec] = std::from_chars(c.data(), c.data() + c.size(), v);
    const bool digits = !c.empty() && c.find_first_not_of("0123456789") == std::string_view::npos;
    if (!digits || ec != std::errc() || ptr != c.data() + c.size() || v < 1 || static_cast<std::size_t>(v) > kMaxStudyTrials) {
      bad("trial", i, "is not a trial number in 1.." + std::to_string(kMaxStudyTrials));
    } else {
      out = v;
    }
  }
  void seed(std::size_t i, std::uint64_t& out) {
    const std::string_view c = cells_[i];
    std::uint64_t v = 0;
    const auto [ptr, ec] = std::from_chars(c.data(), c.data() + c.size(), v);
    const bool digits = !c.empty() && c.find_first_not_of("0123456789") == std::string_view::npos;
    if (!digits || ec != std::errc() || ptr != c.data() + c.size()) bad("seed", i, "is not a whole number in 0..18446744073709551615");
    else out = v;
  }
  // A finite decimal number; at least 0 when `nonnegative`.
  void number(std::string_view column, std::size_t i, double& out, bool nonnegative) {
    const ParsedNumber parsed = parse_decimal(cells_[i]);
    if (const auto* why = std::get_if<std::string>(&parsed)) return bad(column, i, *why);
    const double v = std::get<double>(parsed);
    if (nonnegative && v < 0.0) return bad(column, i, "is negative");
    out = v;
  }
  void flag(std::string_view column, std::size_t i, bool& out) {
    if (cells_[i] == "0") out = false;
    else if (cells_[i] == "1") out = true;
    else bad(column, i, "is not 0 or 1");
  }
  // ISO 8601 in UTC to the second: 2026-11-25T16:38:51Z.
  void time(std::size_t i, std::string& out) {
    const std::string_view c = cells_[i];
    const auto digits = [&](std::size_t at, std::size_t n, int max) {
      int v = 0;
      for (std::size_t k = at; k < at + n; ++k) {
        if (c[k] < '0' || c[k] > '9') return false;
        v = v * 10 + (c[k] - '0');
      }
      return v <= max;
    };
    const bool shape = c.size() == 20 && c[4] == '-' && c[7] == '-' && c[10] == 'T' && c[13] == ':' && c[16] == ':' &&
                       c[19] == 'Z';
    const bool fields = shape && digits(0, 4, 9999) && digits(5, 2, 12) && c.substr(5, 2) != "00" && digits(8, 2, 31) &&
                        c.substr(8, 2) != "00" && digits(11, 2, 23) && digits(14, 2, 59) && digits(17, 2, 60);
    if (!fields) bad("time_utc", i, "is not a UTC time such as 2026-11-25T16:38:51Z");
    else out = c;
  }

 private:
  const std::vector<std::string_view>& cells_;
  int line_;
  DiagnosticList& list_;
  bool ok_ = true;
};

}  // namespace

bool parse_row(const std::vector<std::string_view>& cells, int line, DiagnosticList& list, MatchingTrial& row) {
  Cells c(cells, line, list);
  c.participant(0, row.participant);
  c.name("set", 1, row.set);
  c.trial(2, row.trial);
  c.name("presented", 3, row.presented);
  c.name("chosen", 4, row.chosen);
  c.flag("correct", 5, row.correct);
  c.number("rub_s", 6, row.rub_s, true);
  c.number("response_s", 7, row.response_s, true);
  c.number("path_mm", 8, row.path_mm, true);
  c.time(9, row.time_utc);
  if (c.ok() && row.correct != (row.presented == row.chosen)) {
    c.bad("correct", 5, row.correct ? "but the image chosen is not the one presented"
                                    : "but the image chosen is the one presented");
  }
  return c.ok();
}

bool parse_row(const std::vector<std::string_view>& cells, int line, DiagnosticList& list, LocationTrial& row) {
  Cells c(cells, line, list);
  c.participant(0, row.participant);
  c.trial(1, row.trial);
  if (const auto metaphor = parse_location_metaphor(cells[2])) row.metaphor = *metaphor;
  else c.bad("metaphor", 2, "is not roughness or transitionCue");
  c.seed(3, row.seed);
  c.number("target_x_mm", 4, row.target_x_mm, false);
  c.number("target_z_mm", 5, row.target_z_mm, false);
  c.number("mark_x_mm", 6, row.mark_x_mm, false);
  c.number("mark_y_mm", 7, row.mark_y_mm, false);
  c.number("mark_z_mm", 8, row.mark_z_mm, false);
  c.number("error_mm", 9, row.error_mm, true);
  c.number("explore_s", 10, row.explore_s, true);
  c.time(11, row.time_utc);
  if (c.ok()) {
    // The error is the mark's distance from the target in the x-z plane (the intersection is a line
    // along y); a row that says otherwise was not written by the study.
    const double distance = std::hypot(row.mark_x_mm - row.target_x_mm, row.mark_z_mm - row.target_z_mm);
    if (!(std::abs(row.error_mm - distance) <= 1e-9 * std::max(1.0, distance))) {
      c.bad("error_mm", 9, "is not the mark's distance from the target in the x-z plane (" + format_decimal(distance) + " mm)");
    }
  }
  return c.ok();
}

std::string header_line(const std::vector<std::string>& header) {
  std::string line;
  for (std::size_t i = 0; i < header.size(); ++i) {
    if (i > 0) line += ',';
    line += header[i];
  }
  return line;
}

}  // namespace trial_text
}  // namespace vimg
