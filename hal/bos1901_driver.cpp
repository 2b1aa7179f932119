#include "hal/bos1901_driver.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "hal/bos1901_registers.hpp"
#include "hal/device_error.hpp"
#include "hal/rest_on_exit.hpp"

namespace vimg {

using namespace bos1901;

Bos1901Driver::Bos1901Driver(SpiBus& bus, Clock& clock, const ActuatorProfile& profile, Bos1901Options options)
    : bus_(bus), clock_(clock), options_(options) {
  if (profile.rated_voltage_V > 0.0 && options_.full_scale_V > 0.0) {
    gain_ = std::min(1.0, profile.rated_voltage_V / options_.full_scale_V);
  }
}

Bos1901Driver::~Bos1901Driver() {
  try {
    close();
  } catch (const DeviceError&) {
    // Nothing more can be done; the chip's output stage is left as the last transfer set it.
  }
}

std::uint16_t Bos1901Driver::send(std::uint16_t command) {
  const std::array<std::uint8_t, 2> tx{static_cast<std::uint8_t>(command >> 8),
                                       static_cast<std::uint8_t>(command & 0xFF)};
  std::array<std::uint8_t, 2> rx{};
  std::int64_t backoff_us = options_.first_backoff_us;
  for (int attempt = 0;; ++attempt) {
    try {
      bus_.transfer(tx, rx);
      return static_cast<std::uint16_t>((rx[0] << 8) | rx[1]);
    } catch (const DeviceError& error) {
      if (!error.transient() || attempt >= options_.max_retries) {
        throw;
      }
      clock_.sleep_for_us(backoff_us);
      backoff_us *= 2;
    }
  }
}

void Bos1901Driver::open(double sample_rate_hz) {
  const int play = play_code_for_rate(sample_rate_hz);
  if (play < 0) {
    throw std::invalid_argument(bus_.path() + ": the BOS1901 plays 8, 16, 32, 64, 128, 256, 512 or 1024 kHz, not " +
                                std::to_string(sample_rate_hz) + " Hz");
  }
  sample_period_us_ = std::llround(1e6 / sample_rate_hz);
  send(word(kConfig, kConfigReset));
  config_ = static_cast<std::uint16_t>((kIcStatus << kConfigBroadcastShift) | static_cast<unsigned>(play));
  send(word(kConfig, config_));
  const std::uint16_t status = send(word(kConfig, config_));  // SDO now carries IC_STATUS
  known_space_ = status & kStatusFifoSpaceMask;
  if ((status & kStatusEmpty) != 0 && known_space_ == 0) {
    known_space_ = kFifoDepth;  // FIFO_SPACE is 6 bits: an empty 64-entry FIFO may read 0
  }
  stopped_ = false;
  streaming_ = false;
  restart_from_zero_ = false;
  push_sample(0);  // start at 0 V
  config_ = static_cast<std::uint16_t>(config_ | kConfigOutputEnable);
  send(word(kConfig, config_));
  playing_ = true;
}

void Bos1901Driver::handle_status(std::uint16_t status) {
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

void Bos1901Driver::push_sample(std::uint16_t code) {
  while (known_space_ <= 0) {
    clock_.sleep_for_us(sample_period_us_);  // let the chip play one sample out
    handle_status(send(word(kConfig, config_)));
    if (stopped_) return;
  }
  const std::uint16_t status = send(word(kReference, code));
  const bool was_empty = (status & kStatusEmpty) != 0;
  if ((status & kStatusOverTemp) != 0) {
    stop(FaultKind::over_temperature);
    return;
  }
  known_space_ = (was_empty ? kFifoDepth : (status & kStatusFifoSpaceMask)) - 1;
}

void Bos1901Driver::write(std::span<const float> drive, double) {
  if (!playing_ || stopped_) {
    return;
  }
  if (rest_requested()) {
    stop(FaultKind::rest_requested);
    return;
  }
  // Learn the FIFO state once per block: an underrun since the last block shows here.
  handle_status(send(word(kConfig, config_)));
  for (const float sample : drive) {
    if (stopped_) return;
    if (!streaming_) {
      if (restart_from_zero_) {
        push_sample(0);  // restart from 0 V after running dry
        restart_from_zero_ = false;
      }
      streaming_ = true;
    }
    push_sample(sample_code(static_cast<double>(sample) * gain_));
  }
}

void Bos1901Driver::stop(FaultKind why) {
  stopped_ = true;
  config_ = static_cast<std::uint16_t>(config_ & ~kConfigOutputEnable);
  send(word(kConfig, config_));  // output stage off: the actuator goes to 0 V
  faults_.push({why, 0, clock_.now_us()});
}

void Bos1901Driver::close() {
  if (!playing_) {
    return;
  }
  playing_ = false;
  if (!stopped_) {
    push_sample(0);  // end at 0 V
    for (int poll = 0; poll <= kFifoDepth + 1; ++poll) {
      if ((send(word(kConfig, config_)) & kStatusEmpty) != 0) break;
      clock_.sleep_for_us(sample_period_us_);
    }
    clock_.sleep_for_us(sample_period_us_);  // the last sample reaches the output
  }
  config_ = static_cast<std::uint16_t>(config_ & ~kConfigOutputEnable);
  send(word(kConfig, config_));
}

}  // namespace vimg
