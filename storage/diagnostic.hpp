#pragma once
// A message about a file: `FILE:LINE: error: problem` or `FILE:LINE: warning: problem`.
// Messages are for terminals and editors: input quoted in them goes through escape_input(), and a
// file reports at most kMaxDiagnosticsPerFile of them (DiagnosticList), docs/limits.md "Messages".
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "storage/limits.hpp"

namespace vimg {

struct Diagnostic {
  enum class Severity { error, warning };
  Severity severity = Severity::error;
  std::string file;   // as the user named it
  int line = 0;       // 1-based; 0 when the problem is not tied to a line (e.g. I/O errors)
  std::string message;
  // On the line that counts what a DiagnosticList did not keep (take()), the diagnostics not shown.
  std::size_t not_shown_errors = 0;
  std::size_t not_shown_warnings = 0;

  // "FILE:LINE: error: message" (spec section 4); "FILE: error: message" when line is 0. The file
  // name and the message are passed through printable_message(), whoever built them.
  std::string to_string() const;
};

bool has_errors(const std::vector<Diagnostic>& diagnostics);

// The diagnostics one a line (each to_string()), as a dialog or a log shows them; "" for none.
std::string join_diagnostics(const std::vector<Diagnostic>& diagnostics);

// Moves every diagnostic of `from` to the end of `to`, in order.
void append_diagnostics(std::vector<Diagnostic>& to, std::vector<Diagnostic> from);

// Names as a message lists them: "a, b, c" ("" for none).
std::string listed_names(const std::vector<std::string>& names);

// The diagnostics of one file from two passes (say an import, then its result read back), within
// the same bound as one DiagnosticList: `first` then `second`, and when more than `limit`, the last
// warnings and then the last errors are left out and counted on one summary line with those the
// two lists had already counted.
std::vector<Diagnostic> merge_diagnostics(std::vector<Diagnostic> first, std::vector<Diagnostic> second,
                                          const std::string& file, std::size_t limit = kMaxDiagnosticsPerFile);

// Input shown in a message: ASCII controls (0-31, 127), C1 controls (U+0080-U+009F), bidirectional
// overrides and bytes that are not UTF-8 become \xNN, a backslash becomes \\, valid UTF-8 text stays.
// The result is cut after at most `max_bytes` and then ends in "...".
std::string escape_input(std::string_view text, std::size_t max_bytes = kMaxQuotedInputBytes);

// A byte as messages name it: "0x1B" (a control character, a register, a bus address).
std::string hex_byte(unsigned char byte);

// A whole message made safe to print: escaped like escape_input() except that backslashes stay as
// they are (so an escaped message is unchanged), at most kMaxMessageBytes long ("..." at a cut).
std::string printable_message(std::string_view text);

// The diagnostics of one file. Keeps the first kMaxDiagnosticsPerFile (in line order, ties in the
// order added; or simply in the order added) and counts the rest; take() returns the kept ones in
// that order, followed by one line (FILE: error|warning: N more diagnostics not shown: ...) when
// any were dropped.
class DiagnosticList {
 public:
  enum class Order { by_line, as_added };
  explicit DiagnosticList(std::string file, Order order = Order::as_added, std::size_t limit = kMaxDiagnosticsPerFile);

  // Whether a diagnostic at `line` would be kept. A caller may skip building a message that would
  // not be, and call count() instead.
  bool keeps(int line) const {
    return kept_.size() < limit_ || (order_by_line_ && line < kept_[worst_].diagnostic.line);
  }

  void add(Diagnostic::Severity severity, int line, std::string_view message);
  void error(int line, std::string_view message) { add(Diagnostic::Severity::error, line, message); }
  void warning(int line, std::string_view message) { add(Diagnostic::Severity::warning, line, message); }
  // A diagnostic the caller did not build because keeps() said it would be dropped.
  void count(Diagnostic::Severity severity);

  // Any error so far, kept or dropped.
  bool has_errors() const { return errors_ > 0; }
  const std::string& file() const { return file_; }

  // The kept diagnostics in line order, then the summary line; the list is empty afterwards.
  std::vector<Diagnostic> take();

 private:
  struct Entry {
    Diagnostic diagnostic;
    std::size_t order = 0;
  };
  bool before(const Entry& a, const Entry& b) const {
    if (order_by_line_ && a.diagnostic.line != b.diagnostic.line) return a.diagnostic.line < b.diagnostic.line;
    return a.order < b.order;
  }
  void find_worst();
  void drop(Diagnostic::Severity severity);

  std::string file_;
  bool order_by_line_;
  std::size_t limit_;
  std::vector<Entry> kept_;
  std::size_t worst_ = 0;  // index of the kept entry that sorts last
  std::size_t order_ = 0;
  std::size_t errors_ = 0;
  std::size_t dropped_errors_ = 0;
  std::size_t dropped_warnings_ = 0;
};

}  // namespace vimg
