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
//
// Faults (docs/hardware.md, "Faults and reconnection"): on the render thread a failed trigger is
// retried with backoff; one that still fails is dropped (reported once per episode); ENODEV, or
// failures_until_gone failed triggers in a row, mean the device is gone: the controller posts
// device_gone, takes its DeviceLink down and sends nothing. The device service thread reconnects
// (reconnect(): find and open the device again, read its waveform lists) and puts the link up.
//
// Threads:
//   - control thread: construction, connect(), open(), close(), trigger(), stop_waveforms(),
//     destruction, while neither the render thread nor the device service uses the controller;
//   - render thread: write(). It never throws, allocates, locks or reconnects, and uses the device
//     only while link() is up;
//   - device service thread: faults() (consumer), device_path(), reconnect() while link() is down.
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "realtime/clock.hpp"
#include "hal/update_schedule.hpp"
#include "hal/envelope_follower.hpp"
#include "hal/fault_log.hpp"
#include "hal/transfer_retry.hpp"
#include "hal/hid_device.hpp"
#include "hal/serviced_device.hpp"
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
  int max_retries = 2;                  // after the first attempt
  std::int64_t first_backoff_us = 200;  // doubles each retry
  int failures_until_gone = 5;          // consecutive failed triggers that mean the device is gone
};

class HidHapticController final : public DriveSink, public ServicedDevice {
 public:
  HidHapticController(HidHost& host, std::uint16_t vendor_id, std::uint16_t product_id, Clock& clock,
                      HidHapticOptions options = {});
  ~HidHapticController() override;

  // Finds the device (usage page 0x0E where the backend reports it), opens it and reads its
  // waveform and duration lists. Throws DeviceError / std::runtime_error with the reason.
  void connect();
  const std::vector<HidWaveform>& waveforms() const { return waveforms_; }

  void trigger(std::uint16_t waveform_usage, double intensity, std::uint8_t repeat_count = 0,
               std::uint16_t retrigger_period_ms = 0);
  void stop_waveforms();

  void open(double sample_rate_hz) override;
  void write(std::span<const float> drive, double block_start_time_s) override;
  void close() override;

  FaultLog& faults() override { return faults_; }
  const DeviceLink& link() const override { return link_; }
  const std::string& device_path() const override { return path_; }
  void reconnect() override;
  bool device_gone() const { return !link_.up(); }

 private:
  std::optional<HidWaveform> find(std::uint16_t usage) const;
  template <typename Attempt>
  int retry(Attempt&& attempt);  // 0 or the errno of the last attempt
  // Render thread (and the control thread): false when the trigger failed (reported) or the
  // device is gone.
  bool send_trigger(std::uint8_t ordinal, double intensity, std::uint8_t repeat, std::uint16_t period_ms) noexcept;
  bool account(int error) noexcept;
  void update(std::int64_t time_us) noexcept;
  void resume() noexcept;

  HidHost& host_;
  std::uint16_t vendor_id_;
  std::uint16_t product_id_;
  Clock& clock_;
  HidHapticOptions options_;
  FaultLog faults_;
  DeviceLink link_;
  bool playing_ = false;  // control thread (open, close), read by the render thread

  // Device state: the open device and what it said it plays. Used by whichever thread holds the
  // link.
  std::unique_ptr<HidDevice> device_;
  std::string path_;
  std::vector<HidWaveform> waveforms_;

  // Render thread only (and the control thread in open() and close()).
  EnvelopeFollower follower_;
  UpdateSchedule schedule_;
  TransferAccount transfer_;  // gone: the render thread took the link down and has not seen it up again
  bool active_ = false;
  bool buzzing_ = false;
  bool onset_pending_ = false;
  double last_intensity_ = 0.0;
  std::int64_t onset_us_ = 0;
  std::int64_t last_trigger_us_ = 0;
};

}  // namespace vimg
