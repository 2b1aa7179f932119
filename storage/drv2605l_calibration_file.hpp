#pragma once
// DRV2605L auto-calibration results, stored after a calibration and restored at start-up: the
// driver (hal/drv2605l_driver.hpp) reads and writes its `calibration=FILE` through these functions.
// File format (text, one key=value a line, '#' comments):
//   resonance_hz=175        the profile resonance the calibration was made for
//   a_cal_comp=0x0E         register 0x18
//   a_cal_bemf=0x6F         register 0x19
//   bemf_gain=2             FEEDBACK[1:0]
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "storage/diagnostic.hpp"

namespace vimg {

struct Drv2605lCalibration {
  double resonance_hz = 0.0;
  std::uint8_t a_cal_comp = 0;
  std::uint8_t a_cal_bemf = 0;
  std::uint8_t bemf_gain = 0;
  friend bool operator==(const Drv2605lCalibration&, const Drv2605lCalibration&) = default;
};

// Returns an error message ("FILE: error: ...") or nothing.
std::optional<std::string> save_calibration(const Drv2605lCalibration& calibration,
                                            const std::filesystem::path& path);

struct CalibrationLoadResult {
  std::optional<Drv2605lCalibration> calibration;
  std::vector<Diagnostic> diagnostics;  // one error when calibration is empty and the file exists
  // The error as text ("FILE:LINE: error: problem", "FILE: error: ..." for a read error), or "".
  std::string error() const { return diagnostics.empty() ? std::string() : diagnostics.front().to_string(); }
};
// No file: an empty result without error. Otherwise read through storage/load_file.hpp.
CalibrationLoadResult load_calibration(const std::filesystem::path& path);
// The text of a calibration file (key=value lines); `file_name` names it in messages.
CalibrationLoadResult parse_calibration(std::string_view text, const std::string& file_name);

inline constexpr std::size_t kMaxCalibrationFileBytes = 64 * 1024;

}  // namespace vimg
