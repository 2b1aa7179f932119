#include "storage/diagnostic.hpp"

#include <algorithm>
#include <cstdint>
#include <iterator>

#include "storage/text_bytes.hpp"

namespace vimg {

namespace {

bool hidden_control(std::uint32_t cp) {
  return (cp >= 0x80 && cp <= 0x9F) ||      // C1 controls (0x9B is a CSI)
         (cp >= 0x202A && cp <= 0x202E) ||  // bidirectional embeddings and overrides
         (cp >= 0x2066 && cp <= 0x2069) ||  // bidirectional isolates
         cp == 0x200E || cp == 0x200F || cp == 0x061C;
}

constexpr char kHexDigits[] = "0123456789ABCDEF";

void append_hex(std::string& out, unsigned char b) {
  out += "\\x";
  out += kHexDigits[b >> 4];
  out += kHexDigits[b & 15];
}

// Escapes `text` into at most `max_bytes`, then "..." when input is left over (and `cut` is set).
std::string escape(std::string_view text, std::size_t max_bytes, bool double_backslashes, bool* cut = nullptr) {
  std::string out;
  out.reserve(std::min(text.size(), max_bytes) + 3);
  std::string piece;
  std::size_t i = 0;
  while (i < text.size()) {
    piece.clear();
    const auto b = static_cast<unsigned char>(text[i]);
    std::size_t used = 1;
    if (b < 0x20 || b == 0x7F) {
      append_hex(piece, b);
    } else if (b == '\\' && double_backslashes) {
      piece = "\\\\";
    } else if (b < 0x80) {
      piece = static_cast<char>(b);
    } else {
      std::uint32_t cp = 0;
      const std::size_t n = utf8_sequence(text, i, cp);
      if (n == 0) {
        append_hex(piece, b);
      } else {
        used = n;
        for (std::size_t k = 0; k < n; ++k) {
          if (hidden_control(cp)) append_hex(piece, static_cast<unsigned char>(text[i + k]));
          else piece += text[i + k];
        }
      }
    }
    if (out.size() + piece.size() > max_bytes) break;
    out += piece;
    i += used;
  }
  if (cut != nullptr) *cut = i < text.size();
  if (i < text.size()) out += "...";
  return out;
}

}  // namespace

std::string escape_input(std::string_view text, std::size_t max_bytes) { return escape(text, max_bytes, true); }

std::string printable_message(std::string_view text) {
  // Cheap when the text is already printable and short, which is the common case.
  const bool plain = text.size() <= kMaxMessageBytes && std::all_of(text.begin(), text.end(), [](char c) {
                       const auto b = static_cast<unsigned char>(c);
                       return b >= 0x20 && b < 0x7F;
                     });
  if (plain) return std::string(text);
  bool cut = false;
  std::string whole = escape(text, kMaxMessageBytes, false, &cut);
  if (!cut) return whole;  // fits: so an escaped message passes through unchanged
  return escape(text, kMaxMessageBytes - 3, false);
}

std::string Diagnostic::to_string() const {
  std::string text = printable_message(file);
  if (line > 0) {
    text += ':';
    text += std::to_string(line);
  }
  text += severity == Severity::error ? ": error: " : ": warning: ";
  text += printable_message(message);
  return text;
}

std::string hex_byte(unsigned char byte) { return std::string("0x") + kHexDigits[byte >> 4] + kHexDigits[byte & 15]; }

bool has_errors(const std::vector<Diagnostic>& diagnostics) {
  return std::any_of(diagnostics.begin(), diagnostics.end(),
                     [](const Diagnostic& d) { return d.severity == Diagnostic::Severity::error; });
}

std::string join_diagnostics(const std::vector<Diagnostic>& diagnostics) {
  std::string text;
  for (const Diagnostic& d : diagnostics) {
    if (!text.empty()) text += "\n";
    text += d.to_string();
  }
  return text;
}

void append_diagnostics(std::vector<Diagnostic>& to, std::vector<Diagnostic> from) {
  for (Diagnostic& d : from) to.push_back(std::move(d));
}

std::string listed_names(const std::vector<std::string>& names) {
  std::string text;
  for (const std::string& name : names) text += (text.empty() ? "" : ", ") + name;
  return text;
}

DiagnosticList::DiagnosticList(std::string file, Order order, std::size_t limit)
    : file_(std::move(file)), order_by_line_(order == Order::by_line), limit_(std::max<std::size_t>(limit, 1)) {}

void DiagnosticList::drop(Diagnostic::Severity severity) {
  if (severity == Diagnostic::Severity::error) ++dropped_errors_;
  else ++dropped_warnings_;
}

void DiagnosticList::count(Diagnostic::Severity severity) {
  if (severity == Diagnostic::Severity::error) ++errors_;
  drop(severity);
  ++order_;
}

void DiagnosticList::find_worst() {
  worst_ = 0;
  for (std::size_t i = 1; i < kept_.size(); ++i) {
    if (before(kept_[worst_], kept_[i])) worst_ = i;
  }
}

void DiagnosticList::add(Diagnostic::Severity severity, int line, std::string_view message) {
  if (severity == Diagnostic::Severity::error) ++errors_;
  Entry entry{{severity, file_, line, printable_message(message)}, order_++};
  if (kept_.size() < limit_) {
    kept_.push_back(std::move(entry));
    if (kept_.size() == 1 || before(kept_[worst_], kept_.back())) worst_ = kept_.size() - 1;
    return;
  }
  if (!before(entry, kept_[worst_])) {
    drop(severity);
    return;
  }
  drop(kept_[worst_].diagnostic.severity);
  kept_[worst_] = std::move(entry);
  find_worst();
}

namespace {

// "FILE: error: N more diagnostics not shown: E errors, W warnings (limit L per file)".
Diagnostic not_shown_line(const std::string& file, std::size_t errors, std::size_t warnings, std::size_t limit) {
  const auto counted = [](std::size_t n, const char* what) { return std::to_string(n) + " " + what + (n == 1 ? "" : "s"); };
  std::string parts;
  if (errors > 0) parts = counted(errors, "error");
  if (warnings > 0) parts += (parts.empty() ? "" : ", ") + counted(warnings, "warning");
  const std::size_t dropped = errors + warnings;
  Diagnostic line{errors > 0 ? Diagnostic::Severity::error : Diagnostic::Severity::warning, file, 0,
                  std::to_string(dropped) + " more " + (dropped == 1 ? "diagnostic" : "diagnostics") + " not shown: " +
                      parts + " (limit " + std::to_string(limit) + " per file)"};
  line.not_shown_errors = errors;
  line.not_shown_warnings = warnings;
  return line;
}

}  // namespace

std::vector<Diagnostic> merge_diagnostics(std::vector<Diagnostic> first, std::vector<Diagnostic> second,
                                          const std::string& file, std::size_t limit) {
  std::vector<Diagnostic> shown;
  std::size_t errors = 0, warnings = 0;
  for (std::vector<Diagnostic>* list : {&first, &second}) {
    for (Diagnostic& d : *list) {
      errors += d.not_shown_errors;
      warnings += d.not_shown_warnings;
      if (d.not_shown_errors + d.not_shown_warnings == 0) shown.push_back(std::move(d));
    }
  }
  while (shown.size() > limit) {  // the last warning goes first; errors say why a file failed
    auto last = std::find_if(shown.rbegin(), shown.rend(),
                             [](const Diagnostic& d) { return d.severity == Diagnostic::Severity::warning; });
    if (last == shown.rend()) last = shown.rbegin();
    ++(last->severity == Diagnostic::Severity::error ? errors : warnings);
    shown.erase(std::next(last).base());
  }
  if (errors + warnings > 0) shown.push_back(not_shown_line(file, errors, warnings, limit));
  return shown;
}

std::vector<Diagnostic> DiagnosticList::take() {
  std::sort(kept_.begin(), kept_.end(), [this](const Entry& a, const Entry& b) { return before(a, b); });
  std::vector<Diagnostic> out;
  out.reserve(kept_.size() + 1);
  for (Entry& e : kept_) out.push_back(std::move(e.diagnostic));
  if (dropped_errors_ + dropped_warnings_ > 0) out.push_back(not_shown_line(file_, dropped_errors_, dropped_warnings_, limit_));
  kept_.clear();
  worst_ = 0;
  dropped_errors_ = dropped_warnings_ = 0;
  return out;
}

}  // namespace vimg
