// Fuzzes the message side of storage (storage/diagnostic.hpp): escape_input and printable_message
// turn any bytes into printable, bounded text (no ASCII or C1 controls, no bidirectional
// overrides, valid UTF-8), and DiagnosticList keeps the first diagnostics and counts the rest.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

#include "storage/diagnostic.hpp"
#include "storage/limits.hpp"

namespace {

// Printable: valid UTF-8 without ASCII controls, C1 controls or bidirectional overrides.
void check_printable(std::string_view text) {
  const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(text[i]); };
  for (std::size_t i = 0; i < text.size();) {
    const unsigned char b = byte(i);
    if (b < 0x20 || b == 0x7F) std::abort();
    if (b < 0x80) {
      ++i;
      continue;
    }
    const std::size_t n = b >= 0xF0 ? 4 : b >= 0xE0 ? 3 : b >= 0xC2 ? 2 : 0;
    if (n == 0 || b > 0xF4 || i + n > text.size()) std::abort();
    std::uint32_t cp = b & (n == 2 ? 0x1Fu : n == 3 ? 0x0Fu : 0x07u);
    for (std::size_t k = 1; k < n; ++k) {
      if ((byte(i + k) & 0xC0) != 0x80) std::abort();
      cp = (cp << 6) | (byte(i + k) & 0x3Fu);
    }
    if (cp < 0x80 || (cp >= 0x80 && cp <= 0x9F) || (cp >= 0xD800 && cp <= 0xDFFF) || cp > 0x10FFFF) std::abort();
    if ((cp >= 0x202A && cp <= 0x202E) || (cp >= 0x2066 && cp <= 0x2069)) std::abort();
    i += n;
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const std::size_t max = size > 0 ? data[0] : 0;
  const std::string quoted = vimg::escape_input(text, max);
  check_printable(quoted);
  if (quoted.size() > max + 3) std::abort();
  const std::string message = vimg::printable_message(text);
  check_printable(message);
  if (message.size() > vimg::kMaxMessageBytes) std::abort();
  if (vimg::printable_message(message) != message) std::abort();  // printable text stays as it is
  check_printable(vimg::Diagnostic{vimg::Diagnostic::Severity::error, std::string(text), 3, std::string(text)}.to_string());

  // Bytes as a stream of diagnostics: (severity and order bit, line).
  for (const auto order : {vimg::DiagnosticList::Order::by_line, vimg::DiagnosticList::Order::as_added}) {
    vimg::DiagnosticList list("fuzz", order, 1 + size % 7);
    std::size_t errors = 0, added = 0;
    for (std::size_t i = 0; i + 1 < size; i += 2) {
      const bool error = (data[i] & 1) != 0;
      const int line = data[i + 1] % 16;
      errors += error;
      ++added;
      if ((data[i] & 2) != 0 && !list.keeps(line)) {
        list.count(error ? vimg::Diagnostic::Severity::error : vimg::Diagnostic::Severity::warning);
      } else {
        list.add(error ? vimg::Diagnostic::Severity::error : vimg::Diagnostic::Severity::warning, line, "m");
      }
    }
    if (list.has_errors() != (errors > 0)) std::abort();
    const auto kept = list.take();
    if (kept.size() > 1 + size % 7 + 1) std::abort();
    if (vimg::has_errors(kept) != (errors > 0)) std::abort();  // an error is never lost from sight
    if (order == vimg::DiagnosticList::Order::by_line) {
      for (std::size_t i = 1; i + 1 < kept.size(); ++i) {
        if (kept[i].line < kept[i - 1].line) std::abort();
      }
    }
    if (added <= 1 + size % 7 && kept.size() != added) std::abort();
  }
  return 0;
}
