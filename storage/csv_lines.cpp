#include "storage/csv_lines.hpp"

#include "storage/text_trim.hpp"

namespace vimg {

std::optional<std::string_view> CsvLines::next_line() {
  while (pos_ < text_.size()) {
    std::size_t eol = text_.find('\n', pos_);
    if (eol == std::string_view::npos) eol = text_.size();
    std::string_view line = text_.substr(pos_, eol - pos_);
    pos_ = eol + 1;
    ++line_;
    if (options_.trim_blanks) line = trim_blanks(line);
    else if (line.ends_with('\r')) line.remove_suffix(1);
    if (line.empty() || (options_.comments && line.front() == '#')) continue;
    return line;
  }
  return std::nullopt;
}

std::optional<std::string_view> CsvLines::row() {
  if (past_row_limit_) return std::nullopt;
  const auto line = next_line();
  if (line && ++rows_ > options_.max_rows) {
    past_row_limit_ = true;
    return std::nullopt;
  }
  return line;
}

std::string csv_row_limit_problem(std::size_t max_rows) {
  return "more than " + std::to_string(max_rows) + " rows (limit " + std::to_string(max_rows) + ")";
}

}  // namespace vimg
