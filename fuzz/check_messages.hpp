#pragma once
// What every fuzzer of a file reader checks of its diagnostics: each message is printable (no
// control character reaches a terminal) and bounded, and a file gives at most
// kMaxDiagnosticsPerFile of them plus the line counting the rest. Aborts otherwise.
#include <cstdlib>
#include <vector>

#include "storage/diagnostic.hpp"
#include "storage/limits.hpp"

namespace vimg::fuzz {

inline void check_messages(const std::vector<Diagnostic>& diagnostics) {
  if (diagnostics.size() > kMaxDiagnosticsPerFile + 1) std::abort();
  for (const auto& d : diagnostics) {
    if (d.message.size() > kMaxMessageBytes) std::abort();
    for (const char c : d.to_string()) {
      if (static_cast<unsigned char>(c) < 0x20 || c == 0x7F) std::abort();
    }
  }
}

}  // namespace vimg::fuzz
