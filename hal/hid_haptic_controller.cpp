#include "hal/hid_haptic_controller.hpp"

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "hal/device_error.hpp"
#include "hal/hid_haptics.hpp"
#include "hal/rest_on_exit.hpp"

namespace vimg {

using namespace hid_haptics;

HidHapticController::HidHapticController(HidHost& host, std::uint16_t vendor_id, std::uint16_t product_id,
                                         Clock& clock, HidHapticOptions options)
    : host_(host), vendor_id_(vendor_id), product_id_(product_id), clock_(clock), options_(options) {}

HidHapticController::~HidHapticController() { close(); }

void HidHapticController::connect() {
  device_.reset();
  const auto devices = host_.enumerate(vendor_id_, product_id_);
  const HidDeviceInfo* chosen = nullptr;
  for (const auto& info : devices) {
    if (info.usage_page == kUsagePage || (chosen == nullptr && info.usage_page == 0)) {
      chosen = &info;
      if (info.usage_page == kUsagePage) break;
    }
  }
  char id[16];
  std::snprintf(id, sizeof id, "%04x:%04x", vendor_id_, product_id_);
  if (chosen == nullptr) {
    throw std::runtime_error(std::string("hid:") + id + ": no HID haptic controller (usage page 0x0E) found" +
                             (devices.empty() ? "" : "; the device has no haptics collection"));
  }
  path_ = chosen->path;
  device_ = host_.open(path_);

  std::array<std::uint8_t, 1 + 2 * kMaxWaveforms> list{};
  list[0] = kWaveformListReport;
  const std::size_t got = device_->get_feature_report(list);
  waveforms_.clear();
  for (std::size_t i = 1; i + 1 < got && waveforms_.size() < static_cast<std::size_t>(kMaxWaveforms); i += 2) {
    const auto usage = static_cast<std::uint16_t>(list[i] | (list[i + 1] << 8));
    if (usage == 0) break;
    waveforms_.push_back({static_cast<std::uint8_t>(kFirstDeviceOrdinal + waveforms_.size()), usage, 0});
  }
  if (waveforms_.empty()) {
    throw DeviceError(path_, "the waveform list (feature report 1) is empty or not in the expected layout", 0);
  }
  std::array<std::uint8_t, 1 + 2 * kMaxWaveforms> durations{};
  durations[0] = kDurationListReport;
  const std::size_t got_durations = device_->get_feature_report(durations);
  for (std::size_t i = 0; i < waveforms_.size() && 2 + 2 * i < got_durations; ++i) {
    waveforms_[i].duration_ms = static_cast<std::uint16_t>(durations[1 + 2 * i] | (durations[2 + 2 * i] << 8));
  }
}

void HidHapticController::reconnect() {
  // Service thread, link down: the render thread leaves the device state alone.
  connect();
  link_.put_up();  // the render thread resumes (resume())
}

std::optional<HidWaveform> HidHapticController::find(std::uint16_t usage) const {
  for (const auto& waveform : waveforms_) {
    if (waveform.usage == usage) return waveform;
  }
  return std::nullopt;
}

template <typename Attempt>
int HidHapticController::retry(Attempt&& attempt) {
  return retry_transfer(clock_, options_.max_retries, options_.first_backoff_us, attempt);
}

bool HidHapticController::send_trigger(std::uint8_t ordinal, double intensity, std::uint8_t repeat,
                                       std::uint16_t period_ms) noexcept {
  if (transfer_.gone || !device_) return false;
  const std::array<std::uint8_t, kTriggerReportSize> report{
      kTriggerReport, ordinal, static_cast<std::uint8_t>(std::lround(std::clamp(intensity, 0.0, 1.0) * 100.0)),
      repeat, static_cast<std::uint8_t>(period_ms & 0xFF), static_cast<std::uint8_t>(period_ms >> 8)};
  return account(retry([&] { return device_->try_write(report); }));
}

bool HidHapticController::account(int error) noexcept {
  return transfer_.account(error, options_.failures_until_gone, faults_, link_, clock_);
}

void HidHapticController::trigger(std::uint16_t waveform_usage, double intensity, std::uint8_t repeat_count,
                                  std::uint16_t retrigger_period_ms) {
  const auto waveform = find(waveform_usage);
  if (!waveform) {
    throw std::invalid_argument(path_ + ": the device has no waveform 0x" + std::to_string(waveform_usage));
  }
  send_trigger(waveform->ordinal, intensity, repeat_count, retrigger_period_ms);
}

void HidHapticController::stop_waveforms() { send_trigger(kOrdinalStop, 0.0, 0, 0); }

void HidHapticController::open(double sample_rate_hz) {
  if (!device_ || !link_.up()) {
    connect();
    link_.put_up();
  }
  transfer_.reset();
  follower_.configure(sample_rate_hz, options_.resonance_hz, 0.003);
  schedule_.start(sample_rate_hz, 1000.0);  // 1 kHz decisions
  active_ = buzzing_ = onset_pending_ = false;
  playing_ = true;
}

void HidHapticController::write(std::span<const float> drive, double block_start_time_s) {
  if (!playing_) return;
  if (rest_requested()) {
    close();
    return;
  }
  schedule_.feed(
      drive, block_start_time_s, clock_, [this](float x) { follower_.push(x); },
      [this](std::int64_t time_us) { update(time_us); });
}

void HidHapticController::resume() noexcept {
  // reconnect() found and opened the device again; nothing plays on it yet.
  transfer_.reset();
  active_ = buzzing_ = onset_pending_ = false;
}

void HidHapticController::update(std::int64_t time_us) noexcept {
  if (transfer_.gone) {
    if (!link_.up()) {
      return;  // the service is reconnecting: nothing is sent
    }
    resume();
  }
  const double level = follower_.envelope();
  const auto click = find(kWaveformClick);
  const auto buzz = find(kWaveformBuzz);
  const auto carrier_period_us = std::llround(1e6 / options_.resonance_hz);
  if (!active_ && level >= options_.onset_threshold) {
    active_ = true;
    onset_pending_ = true;
    buzzing_ = false;
    onset_us_ = time_us;
    last_intensity_ = level;
    return;
  }
  if (active_) last_intensity_ = onset_pending_ ? std::max(last_intensity_, level) : last_intensity_;
  // The onset plays once the carrier's first period has shown its peak (or the drive ended).
  if (onset_pending_ && (time_us - onset_us_ >= carrier_period_us || level < options_.onset_threshold)) {
    onset_pending_ = false;
    const auto onset = click ? click : buzz;
    if (onset) send_trigger(onset->ordinal, last_intensity_, 0, 0);
    last_trigger_us_ = time_us;
  }
  if (active_ && level < options_.onset_threshold) {
    active_ = false;
    if (buzzing_) send_trigger(kOrdinalStop, 0.0, 0, 0);
    buzzing_ = false;
    return;
  }
  if (!active_ || onset_pending_) return;
  const std::int64_t click_us = (click && click->duration_ms > 0 ? click->duration_ms : 20) * 1000LL;
  const std::int64_t sustained_after_us = std::max<std::int64_t>(click_us, std::llround(options_.sustain_after_s * 1e6)) + carrier_period_us;
  const bool changed = std::fabs(level - last_intensity_) > options_.intensity_step;
  const bool may_retrigger = time_us - last_trigger_us_ >= std::llround(options_.min_retrigger_interval_s * 1e6);
  if (time_us - onset_us_ >= sustained_after_us && may_retrigger && (!buzzing_ || changed)) {
    const auto sustained = buzz ? buzz : click;
    if (!sustained) return;
    const std::uint16_t period_ms = sustained->duration_ms > 0 ? sustained->duration_ms : 20;
    if (send_trigger(sustained->ordinal, level, 255, period_ms)) {
      buzzing_ = true;
      last_intensity_ = level;
      last_trigger_us_ = time_us;
    }
  }
}

void HidHapticController::close() {
  if (!playing_) return;
  playing_ = false;
  if (!link_.up()) return;  // gone: nothing reaches the device
  resume();                 // the service may have reconnected it since the last write()
  send_trigger(kOrdinalStop, 0.0, 0, 0);
}

}  // namespace vimg
