#include "storage/drv2605l_calibration_file.hpp"

#include <system_error>

#include "storage/atomic_file.hpp"
#include "storage/diagnostic.hpp"
#include "storage/load_file.hpp"

#include <charconv>
#include <cstdio>
#include <sstream>

namespace vimg {

std::optional<std::string> save_calibration(const Drv2605lCalibration& calibration,
                                            const std::filesystem::path& path) {
  char text[256];
  std::snprintf(text, sizeof text,
                "# DRV2605L auto-calibration results (vibroimage)\nresonance_hz=%.3f\na_cal_comp=0x%02X\n"
                "a_cal_bemf=0x%02X\nbemf_gain=%u\n",
                calibration.resonance_hz, calibration.a_cal_comp, calibration.a_cal_bemf,
                static_cast<unsigned>(calibration.bemf_gain));
  if (auto error = write_file_atomically(path, text)) {
    return path.string() + ": error: cannot write the calibration file (" + *error + ")";
  }
  return std::nullopt;
}

CalibrationLoadResult load_calibration(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) return {};  // no file: nothing to restore
  return load_file<CalibrationLoadResult>(path, kMaxCalibrationFileBytes, parse_calibration);
}

CalibrationLoadResult parse_calibration(std::string_view text, const std::string& file_name) {
  CalibrationLoadResult result;
  std::istringstream in{std::string(text)};
  Drv2605lCalibration calibration;
  bool seen[4] = {false, false, false, false};
  std::string line;
  int line_number = 0;
  auto fail = [&](const std::string& problem) {
    result.diagnostics.push_back(Diagnostic{Diagnostic::Severity::error, file_name, line_number, problem});
    return result;
  };
  while (std::getline(in, line)) {
    ++line_number;
    if (line.empty() || line[0] == '#') continue;
    const auto equals = line.find('=');
    if (equals == std::string::npos) return fail("expected key=value");
    const std::string key = line.substr(0, equals);
    std::string value = line.substr(equals + 1);
    if (key == "resonance_hz") {
      std::istringstream stream(value);
      stream.imbue(std::locale::classic());
      if (!(stream >> calibration.resonance_hz) || calibration.resonance_hz <= 0.0) {
        return fail("resonance_hz must be a positive number");
      }
      seen[0] = true;
      continue;
    }
    int base = 10;
    std::string_view digits = value;
    if (digits.starts_with("0x")) {
      digits.remove_prefix(2);
      base = 16;
    }
    unsigned number = 0;
    const auto [end, status] = std::from_chars(digits.data(), digits.data() + digits.size(), number, base);
    if (status != std::errc() || end != digits.data() + digits.size() || number > 255) {
      return fail("'" + escape_input(key) + "' must be a byte value, not '" + escape_input(value) + "'");
    }
    if (key == "a_cal_comp") {
      calibration.a_cal_comp = static_cast<std::uint8_t>(number);
      seen[1] = true;
    } else if (key == "a_cal_bemf") {
      calibration.a_cal_bemf = static_cast<std::uint8_t>(number);
      seen[2] = true;
    } else if (key == "bemf_gain") {
      if (number > 3) return fail("bemf_gain must be 0..3");
      calibration.bemf_gain = static_cast<std::uint8_t>(number);
      seen[3] = true;
    } else {
      return fail("unknown key '" + escape_input(key) + "'");
    }
  }
  if (!(seen[0] && seen[1] && seen[2] && seen[3])) {
    return fail("needs resonance_hz, a_cal_comp, a_cal_bemf and bemf_gain");
  }
  result.calibration = calibration;
  return result;
}

}  // namespace vimg
