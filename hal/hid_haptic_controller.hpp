#pragma once
// A USB HID Simple Haptic Controller as a DriveSink. It cannot take a sample stream: it plays its
// own waveforms on request. Mapping of the drive (see docs/hardware.md):
//   - an onset (envelope rising above onset_threshold) triggers CLICK one carrier period later at
//     the envelope's peak intensity: a DOT crossing, or the strike of a LINE whose ring-down follows;
//   - drive that stays above the threshold longer than max(click, sustain_after_s) plus one carrier
//     period (a SURFACE texture, a long ring)
//     becomes BUZZ, repeated every retrigger period, its intensity following the envelope (a new
//     trigger when it changes by more than intensity_step);
//   - the envelope falling below the threshold triggers STOP.
// Devices without CLICK use BUZZ for onsets; without BUZZ, sustained drive repeats CLICK.
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "realtime/clock.hpp"
#include "hal/update_schedule.hpp"
#include "hal/envelope_follower.hpp"
#include "hal/fault_log.hpp"
#include "hal/hid_device.hpp"
#include "player/drive_sink.hpp"

namespace vimg {

struct HidWaveform {
  std::uint8_t ordinal = 0;
  std::uint16_t usage = 0;
  std::uint16_t duration_ms = 0;
};

struct HidHapticOptions {
  double onset_threshold = 0.05;
  double intensity_step = 0.1;
  double min_retrigger_interval_s = 0.02;
  double sustain_after_s = 0.030;  // drive longer than this (and the click) is sustained
  double resonance_hz = 175.0;  // the envelope follower's nominal carrier
};

class HidHapticController final : public DriveSink {
 public:
  HidHapticController(HidHost& host, std::uint16_t vendor_id, std::uint16_t product_id, Clock& clock,
                      HidHapticOptions options = {});
  ~HidHapticController() override;

  // Finds the device (usage page 0x0E where the backend reports it), opens it and reads its
  // waveform and duration lists. Throws DeviceError / std::runtime_error with the reason.
  void connect();
  const std::vector<HidWaveform>& waveforms() const { return waveforms_; }
  const std::string& device_path() const { return path_; }

  void trigger(std::uint16_t waveform_usage, double intensity, std::uint8_t repeat_count = 0,
               std::uint16_t retrigger_period_ms = 0);
  void stop_waveforms();

  void open(double sample_rate_hz) override;
  void write(std::span<const float> drive, double block_start_time_s) override;
  void close() override;

  FaultLog& faults() { return faults_; }

 private:
  std::optional<HidWaveform> find(std::uint16_t usage) const;
  bool send_trigger(std::uint8_t ordinal, double intensity, std::uint8_t repeat, std::uint16_t period_ms);
  void update(std::int64_t time_us);

  HidHost& host_;
  std::uint16_t vendor_id_;
  std::uint16_t product_id_;
  Clock& clock_;
  HidHapticOptions options_;
  std::unique_ptr<HidDevice> device_;
  std::string path_;
  std::vector<HidWaveform> waveforms_;
  FaultLog faults_;
  EnvelopeFollower follower_;
  UpdateSchedule schedule_;
  bool playing_ = false;
  bool active_ = false;
  bool buzzing_ = false;
  bool onset_pending_ = false;
  bool gone_ = false;
  double last_intensity_ = 0.0;
  std::int64_t onset_us_ = 0;
  std::int64_t last_trigger_us_ = 0;
  std::int64_t last_reconnect_us_ = 0;
};

}  // namespace vimg
