#pragma once
// The lines of a small CSV file as its readers take them (probe paths, gesture recordings, the
// location study's mark times, the matching study's responses): split at '\n' and numbered from 1,
// the '\r' a Windows file leaves at a line's end removed (or every blank around the line, where the
// format allows them), blank lines and, where the format has them, comment lines starting with '#'
// passed over. The first line left is the header, the others are the rows, counted against the
// format's row limit. What a line must hold, and every message about it, stays with its reader.
#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <string_view>

namespace vimg {

// "more than N rows (limit N)": a CSV file with more rows than its format allows.
std::string csv_row_limit_problem(std::size_t max_rows);

class CsvLines {
 public:
  struct Options {
    bool trim_blanks = false;  // spaces and tabs at both ends go too (storage/text_trim.hpp), not only one '\r'
    bool comments = true;      // a line starting with '#' (after trimming) is passed over
    std::size_t max_rows = std::numeric_limits<std::size_t>::max();  // rows after the header
  };

  explicit CsvLines(std::string_view text) : CsvLines(text, Options{}) {}
  CsvLines(std::string_view text, Options options) : text_(text), options_(options) {}

  // The first line neither blank nor a comment; nullopt when the text has none. Read it first.
  std::optional<std::string_view> header() { return next_line(); }

  // The next row; nullopt at the end of the text, or at the first row past max_rows, after which
  // past_row_limit() is true, line() is that row's and row_limit_problem() says so.
  std::optional<std::string_view> row();

  // The number of the line last read (lines passed over count); at the end, the text's last line.
  int line() const { return line_; }
  bool past_row_limit() const { return past_row_limit_; }
  // "more than N rows (limit N)"
  std::string row_limit_problem() const { return csv_row_limit_problem(options_.max_rows); }

 private:
  std::optional<std::string_view> next_line();

  std::string_view text_;
  Options options_;
  std::size_t pos_ = 0;
  int line_ = 0;
  std::size_t rows_ = 0;
  bool past_row_limit_ = false;
};

}  // namespace vimg
