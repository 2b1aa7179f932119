#pragma once
// Rendered signals as inputs of `vimg compare` (docs/studies.md): a signal is compared as it is,
// sample for sample with the renders of the images, so it must be at the comparison's rate
// (kCompareRateHz, 8 kHz, what `vimg render` writes by default). A signal at another rate is
// refused with the way to get it at 8 kHz (`vimg render --rate 8000`) rather than resampled: any
// resampler would add its own filter to what the metric compares.
//   - WAV: RIFF/WAVE, mono, 32-bit IEEE float (format 3, as `vimg render` writes) or 16-bit PCM
//     (format 1, scaled to [-1, 1)); WAVE_FORMAT_EXTENSIBLE with either subformat. Other chunks are
//     skipped. Problems are "FILE: error: ..." (a binary file has no lines).
//   - CSV: the header `time_s,drive` or `time_s,acceleration` (`vimg render --out X.csv`), then one
//     `time,value` row per sample, the times 1/8000 s apart (within a quarter of a sample period).
//     Problems are "FILE:LINE: error: ...".
// Both: at most kMaxSignalFileBytes, read through storage/read_file.hpp; at most kMaxSignalDurationS
// of samples; every value finite. Pure functions of the file's bytes.
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "primitives/perception/perception_rate.hpp"
#include "storage/diagnostic.hpp"

namespace vimg {

inline constexpr double kCompareRateHz = kPerceptionRateHz;

struct SignalReadResult {
  std::optional<std::vector<float>> samples;  // set only when there is no error
  std::vector<Diagnostic> diagnostics;
  bool ok() const { return samples.has_value(); }
};

// `file_name` is used in messages only.
SignalReadResult parse_wav_signal(std::string_view bytes, const std::string& file_name);
SignalReadResult parse_csv_signal(std::string_view text, const std::string& file_name);

// Reads a `.wav` or `.csv` file, chosen by the extension.
SignalReadResult read_signal_file(const std::filesystem::path& path);

}  // namespace vimg
