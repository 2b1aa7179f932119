#include "hal/bos1901_driver.hpp"

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <stdexcept>

#include "hal/bos1901_registers.hpp"
#include "hal/device_error.hpp"
#include "hal/rest_on_exit.hpp"

namespace vimg {

using namespace bos1901;

namespace {

std::array<std::uint8_t, 2> bytes_of(std::uint16_t word) {
  return {static_cast<std::uint8_t>(word >> 8), static_cast<std::uint8_t>(word & 0xFF)};
}

std::uint16_t word_of(const std::array<std::uint8_t, 2>& bytes) {
  return static_cast<std::uint16_t>((bytes[0] << 8) | bytes[1]);
}

}  // namespace

Bos1901Driver::Bos1901Driver(SpiBus& bus, Clock& clock, const ActuatorProfile& profile, Bos1901Options options)
    : bus_(bus), clock_(clock), options_(options) {
  if (profile.rated_voltage_V > 0.0 && options_.full_scale_V > 0.0) {
    gain_ = std::min(1.0, profile.rated_voltage_V / options_.full_scale_V);
  }
}

Bos1901Driver::~Bos1901Driver() { close(); }

template <typename Attempt>
int Bos1901Driver::retry(Attempt&& attempt) {
  return retry_transfer(clock_, options_.max_retries, options_.first_backoff_us, attempt);
}

std::uint16_t Bos1901Driver::send(std::uint16_t command) {
  const auto tx = bytes_of(command);
  std::array<std::uint8_t, 2> rx{};
  const int error = retry([&] {
    try {
      bus_.transfer(tx, rx);
      return 0;
    } catch (const DeviceError& failure) {
      return failure.error_number() != 0 ? failure.error_number() : EIO;
    }
  });
  if (error != 0) {
    throw DeviceError(bus_.path(), "BOS1901: SPI word " + std::to_string(command), error);
  }
  return word_of(rx);
}

bool Bos1901Driver::exchange(std::uint16_t command, std::uint16_t& sdo) noexcept {
  if (transfer_.gone) return false;
  const auto tx = bytes_of(command);
  std::array<std::uint8_t, 2> rx{};
  if (!account(retry([&] { return bus_.try_transfer(tx, rx); }))) return false;
  sdo = word_of(rx);
  return true;
}

bool Bos1901Driver::account(int error) noexcept {
  return transfer_.account(error, options_.failures_until_gone, faults_, link_, clock_);
}

void Bos1901Driver::start_stream() {
  send(word(kConfig, kConfigReset));
  config_ = static_cast<std::uint16_t>((kIcStatus << kConfigBroadcastShift) | static_cast<unsigned>(play_code_));
  send(word(kConfig, config_));
  const std::uint16_t status = send(word(kConfig, config_));  // SDO now carries IC_STATUS
  known_space_ = status & kStatusFifoSpaceMask;
  if ((status & kStatusEmpty) != 0 && known_space_ == 0) {
    known_space_ = kFifoDepth;  // FIFO_SPACE is 6 bits: an empty 64-entry FIFO may read 0
  }
  streaming_ = false;
  restart_from_zero_ = false;
  const std::uint16_t before_zero = send(word(kReference, 0));  // start at 0 V
  known_space_ = ((before_zero & kStatusEmpty) != 0 ? kFifoDepth : (before_zero & kStatusFifoSpaceMask)) - 1;
  config_ = static_cast<std::uint16_t>(config_ | kConfigOutputEnable);
  send(word(kConfig, config_));
}

void Bos1901Driver::open(double sample_rate_hz) {
  const int play = play_code_for_rate(sample_rate_hz);
  if (play < 0) {
    throw std::invalid_argument(bus_.path() + ": the BOS1901 plays 8, 16, 32, 64, 128, 256, 512 or 1024 kHz, not " +
                                std::to_string(sample_rate_hz) + " Hz");
  }
  play_code_ = play;
  sample_period_us_ = std::llround(1e6 / sample_rate_hz);
  if (!link_.up()) {
    bus_.reopen();
  }
  start_stream();
  link_.put_up();
  transfer_.reset();
  stopped_ = false;
  playing_ = true;
}

void Bos1901Driver::reconnect() {
  // Service thread, link down: the render thread leaves the bus and the device state alone.
  bus_.reopen();
  if (playing_) {
    start_stream();
  } else {
    send(word(kConfig, kConfigReset));  // output stage off
  }
  link_.put_up();  // after the last transfer: the render thread resumes
}

void Bos1901Driver::handle_status(std::uint16_t status) noexcept {
  if ((status & kStatusOverTemp) != 0) {
    stop(FaultKind::over_temperature);
    return;
  }
  const bool empty = (status & kStatusEmpty) != 0;
  known_space_ = empty ? kFifoDepth : (status & kStatusFifoSpaceMask);
  if (empty && streaming_) {
    // Ran dry while streaming: the chip holds the last sample. Restart from 0 V.
    underruns_.fetch_add(1, std::memory_order_relaxed);
    faults_.push({FaultKind::underrun, 0, clock_.now_us()});
    streaming_ = false;
    restart_from_zero_ = true;
  }
}

bool Bos1901Driver::push_sample(std::uint16_t code) noexcept {
  std::uint16_t status = 0;
  while (known_space_ <= 0) {
    clock_.sleep_for_us(sample_period_us_);  // let the chip play one sample out
    if (!exchange(word(kConfig, config_), status)) return false;
    handle_status(status);
    if (stopped_) return false;
  }
  if (!exchange(word(kReference, code), status)) return false;
  if ((status & kStatusOverTemp) != 0) {
    stop(FaultKind::over_temperature);
    return false;
  }
  const bool was_empty = (status & kStatusEmpty) != 0;
  known_space_ = (was_empty ? kFifoDepth : (status & kStatusFifoSpaceMask)) - 1;
  return true;
}

void Bos1901Driver::write(std::span<const float> drive, double) {
  if (!playing_ || stopped_) {
    keep_pace(drive.size());
    return;
  }
  if (transfer_.gone) {
    if (!link_.up()) {
      keep_pace(drive.size());  // the service is reconnecting: output is skipped, the bus left alone
      return;
    }
    // reconnect() restarted the stream from 0 V.
    transfer_.reset();
  }
  if (rest_requested()) {
    stop(FaultKind::rest_requested);
    keep_pace(drive.size());
    return;
  }
  // Learn the FIFO state once per block: an underrun since the last block shows here.
  std::uint16_t status = 0;
  if (exchange(word(kConfig, config_), status)) {
    handle_status(status);
  }
  for (std::size_t i = 0; i < drive.size(); ++i) {
    if (stopped_ || transfer_.gone) {
      keep_pace(drive.size() - i);
      return;
    }
    if (!streaming_) {
      if (restart_from_zero_) {
        if (!push_sample(0)) continue;  // restart from 0 V after running dry
        restart_from_zero_ = false;
      }
      streaming_ = true;
    }
    push_sample(sample_code(static_cast<double>(drive[i]) * gain_));  // a failed word is a lost sample
  }
}

void Bos1901Driver::keep_pace(std::size_t samples) noexcept {
  // Consecutive skipped blocks continue from the previous deadline, so they keep the stream rate.
  skip_until_us_ = std::max(skip_until_us_, clock_.now_us()) +
                   static_cast<std::int64_t>(samples) * sample_period_us_;
  clock_.sleep_until_us(skip_until_us_);
}

void Bos1901Driver::stop(FaultKind why) noexcept {
  stopped_ = true;
  config_ = static_cast<std::uint16_t>(config_ & ~kConfigOutputEnable);
  std::uint16_t status = 0;
  exchange(word(kConfig, config_), status);  // output stage off: the actuator goes to 0 V
  faults_.push({why, 0, clock_.now_us()});
}

void Bos1901Driver::close() {
  if (!playing_) {
    return;
  }
  playing_ = false;
  if (!link_.up()) {
    return;  // gone: nothing reaches the chip
  }
  transfer_.gone = false;  // the service may have reconnected it since the last write()
  std::uint16_t status = 0;
  if (!stopped_ && push_sample(0)) {  // end at 0 V
    for (int poll = 0; poll <= kFifoDepth + 1; ++poll) {
      if (!exchange(word(kConfig, config_), status) || (status & kStatusEmpty) != 0) break;
      clock_.sleep_for_us(sample_period_us_);
    }
    clock_.sleep_for_us(sample_period_us_);  // the last sample reaches the output
  }
  config_ = static_cast<std::uint16_t>(config_ & ~kConfigOutputEnable);
  exchange(word(kConfig, config_), status);
}

}  // namespace vimg
