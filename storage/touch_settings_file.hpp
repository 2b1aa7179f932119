#pragma once
// The touch-latency settings a program keeps on this device (docs/latency.md, "Settings"): the
// editor writes its Mode menu's choice here so that the next session on the same machine starts
// with it. A small text file, one `key = value` a line, `#` comments and blank lines ignored:
//   # vimg-editor: touch-latency compensation on this device (docs/latency.md)
//   touch_latency_ms = 8
//   touch_prediction = on
// touch_latency_ms: 0 to kMaxTouchPanelLatency_s in ms, decimals allowed; touch_prediction: on or
// off. A missing key keeps the program's default; an unknown key, a bad value or a repeated key is
// an error on its line (FILE:LINE: error: ...) and that line is ignored. Read through
// read_regular_file (at most kMaxTouchSettingsBytes), written atomically.
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "storage/diagnostic.hpp"

namespace vimg {

inline constexpr std::size_t kMaxTouchSettingsBytes = 4096;

struct TouchSettings {
  std::optional<double> latency_ms;
  std::optional<bool> prediction;
};

struct TouchSettingsRead {
  TouchSettings settings;               // what the valid lines set
  std::vector<Diagnostic> diagnostics;  // errors on the lines that were ignored
};

// The parser on its own (tests and the fuzzer); `file` names the file in the messages.
TouchSettingsRead parse_touch_settings(std::string_view text, const std::string& file);

// Reads `path`; a file that does not exist is no error (every key keeps its default).
TouchSettingsRead read_touch_settings(const std::filesystem::path& path);

// The file's text for `latency_ms` and `prediction` (`program` names the writer in the comment).
std::string touch_settings_text(double latency_ms, bool prediction, std::string_view program);

// Writes it atomically; the error, naming the path, or nothing.
std::optional<std::string> write_touch_settings(const std::filesystem::path& path, double latency_ms,
                                                bool prediction, std::string_view program);

}  // namespace vimg
