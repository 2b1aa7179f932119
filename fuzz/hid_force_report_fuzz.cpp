// Fuzzes the HID force protocol as the host reads it from a device: the info feature report
// (with its slew byte) and a stream of input reports. Any bytes decode to finite, in-range limits
// (a positive slew limit, the default when the byte is 0) or to nothing; a decoded info report
// survives encode/decode unchanged; and HidForceDevice, reading the bytes as state reports, never
// crashes, never lets its measurement count go backwards, and reports a fault code on failure.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <span>
#include <string>

#include "hal/force/hid_force_device.hpp"

namespace {

bool finite(const vimg::Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// The device side: a valid info report, then the fuzz bytes as input reports of 16 bytes (the
// state report's size; the last one shorter).
class FuzzTransport final : public vimg::HidTransport {
 public:
  explicit FuzzTransport(std::span<const std::uint8_t> bytes) : bytes_(bytes) {}
  int write(std::span<const std::uint8_t> report) override { return static_cast<int>(report.size()); }
  int read(std::span<std::uint8_t> buffer, int) override {
    if (bytes_.empty()) return 0;
    const std::size_t n = std::min<std::size_t>({bytes_.size(), buffer.size(), vimg::hid_force::kStateReportSize});
    std::copy_n(bytes_.begin(), n, buffer.begin());
    bytes_ = bytes_.subspan(n);
    return static_cast<int>(n);
  }
  int get_feature_report(std::span<std::uint8_t> buffer) override {
    const auto info = vimg::hid_force::encode_info({});
    std::copy_n(info.begin(), std::min(buffer.size(), info.size()), buffer.begin());
    return static_cast<int>(info.size());
  }

 private:
  std::span<const std::uint8_t> bytes_;
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::span<const std::uint8_t> bytes(data, size);
  if (const auto info = vimg::hid_force::decode_info(bytes)) {
    const vimg::ForceDeviceLimits& l = info->limits;
    if (!(l.max_slew_N_per_ms > 0.0 && l.max_slew_N_per_ms <= 25.5)) std::abort();
    if (!std::isfinite(l.max_force_N) || l.max_force_N < 0.0 || !finite(l.workspace_m)) std::abort();
    const auto again = vimg::hid_force::decode_info(vimg::hid_force::encode_info(*info));
    if (!again || again->limits.max_slew_N_per_ms != l.max_slew_N_per_ms || again->limits.max_force_N != l.max_force_N ||
        again->report_rate_hz != info->report_rate_hz || again->button_count != info->button_count) {
      std::abort();
    }
  }
  if (const auto state = vimg::hid_force::decode_state(bytes)) {
    if (!finite(state->position_m)) std::abort();
  }
  if (const auto force = vimg::hid_force::decode_force(bytes)) {
    if (!finite(force->force_N) || vimg::norm(force->force_N) > 32.767 * std::sqrt(3.0) + 1e-9) std::abort();
  }

  std::string error;
  auto device = vimg::HidForceDevice::open(std::make_unique<FuzzTransport>(bytes), error);
  if (!device) std::abort();  // the info report is valid
  vimg::ProbeSample sample;
  std::uint64_t last_sequence = 0;
  for (int i = 0; i < 64; ++i) {
    if (device->read(i * 1e-3, sample)) {
      if (sample.sequence < last_sequence || !finite(sample.position_m) || !finite(sample.velocity_m_per_s)) std::abort();
      last_sequence = sample.sequence;
    } else if (device->last_fault() == vimg::PortFault::none) {
      std::abort();  // a failed read always says why
    }
  }
  return 0;
}
