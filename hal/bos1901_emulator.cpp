#include "hal/bos1901_emulator.hpp"

#include <cerrno>
#include <cmath>

#include "hal/device_error.hpp"

namespace vimg {

using namespace bos1901;

Bos1901Emulator::Bos1901Emulator(Clock& clock, std::string path) : clock_(clock), path_(std::move(path)) {
  power_on_state();
}

void Bos1901Emulator::power_on_state() {
  config_ = 7;  // 8 ksps, output disabled
  fifo_head_ = 0;
  fifo_count_ = 0;
  output_ = 0;
  over_temperature_ = false;
  was_playing_ = false;
}

void Bos1901Emulator::advance() {
  const auto now = static_cast<double>(clock_.now_us());
  if (!output_enabled()) {
    play_phase_us_ = now;
    return;
  }
  // One FIFO entry reaches the output every sample period.
  while (play_phase_us_ + sample_period_us_ <= now) {
    play_phase_us_ += sample_period_us_;
    if (fifo_count_ == 0) {
      if (was_playing_ && output_ != 0) {
        ++underruns_;  // ran dry while driving: the output is stuck away from 0 V
      }
      was_playing_ = false;
      play_phase_us_ = now;
      break;
    }
    output_ = fifo_[static_cast<std::size_t>(fifo_head_)];
    fifo_head_ = (fifo_head_ + 1) % kFifoDepth;
    --fifo_count_;
    was_playing_ = true;
    played_.push_back({static_cast<std::int64_t>(play_phase_us_), output_});
  }
}

std::uint16_t Bos1901Emulator::broadcast_value() const {
  const unsigned selected = (config_ >> kConfigBroadcastShift) & 0x1Fu;
  std::uint16_t value = 0;
  if (selected == kIcStatus) {
    const int level = fifo_count_;
    value = static_cast<std::uint16_t>((kFifoDepth - level) & kStatusFifoSpaceMask);
    if (level == 0) value |= kStatusEmpty;
    if (level == kFifoDepth) value = static_cast<std::uint16_t>(value | kStatusFull);
    if (over_temperature_) value |= kStatusOverTemp;
  } else if (selected == kConfig) {
    value = config_;
  }
  return word(static_cast<std::uint8_t>(selected), value);
}

void Bos1901Emulator::execute(std::uint16_t command) {
  const unsigned reg = command >> 12;
  const std::uint16_t value = command & 0xFFFu;
  if (reg == kReference) {
    if (fifo_count_ >= kFifoDepth) {
      ++overflows_;
      return;
    }
    fifo_[static_cast<std::size_t>((fifo_head_ + fifo_count_) % kFifoDepth)] = sample_value(value);
    ++fifo_count_;
    max_level_ = std::max(max_level_, fifo_count_);
  } else if (reg == kConfig) {
    if ((value & kConfigReset) != 0) {
      ++resets_;
      power_on_state();
      return;
    }
    const bool enabling = (value & kConfigOutputEnable) != 0 && !output_enabled();
    config_ = value;
    sample_period_us_ = 1e6 / rate_for_play_code(value & 7u);
    if (enabling) {
      play_phase_us_ = static_cast<double>(clock_.now_us());
    }
    if ((value & kConfigOutputEnable) == 0) {
      output_ = 0;  // output stage off: the actuator discharges to 0 V
    }
  }
}

int Bos1901Emulator::exchange(std::span<const std::uint8_t> tx, std::span<std::uint8_t> rx) noexcept {
  if (unplugged_.load(std::memory_order_relaxed) || needs_reopen_) {
    if (!needs_reopen_) {
      advance();
      power_on_state();  // the chip lost its supply with its cable
    }
    needs_reopen_ = true;
    return ENODEV;
  }
  if (failures_left_ > 0) {
    --failures_left_;
    return failure_errno_;
  }
  if (!rx.empty() && rx.size() != tx.size()) {
    return EINVAL;
  }
  advance();
  for (std::size_t i = 0; i + 1 < tx.size(); i += 2) {
    const std::uint16_t sdo = broadcast_value();  // shifted out while the new word shifts in
    if (!rx.empty()) {
      rx[i] = static_cast<std::uint8_t>(sdo >> 8);
      rx[i + 1] = static_cast<std::uint8_t>(sdo & 0xFF);
    }
    execute(static_cast<std::uint16_t>((tx[i] << 8) | tx[i + 1]));
  }
  return 0;
}

void Bos1901Emulator::transfer(std::span<const std::uint8_t> tx, std::span<std::uint8_t> rx) {
  throwing_transfers_.fetch_add(1, std::memory_order_relaxed);
  if (const int error = exchange(tx, rx)) {
    throw DeviceError(path_, "SPI transfer", error);
  }
}

int Bos1901Emulator::try_transfer(std::span<const std::uint8_t> tx, std::span<std::uint8_t> rx) noexcept {
  const int error = exchange(tx, rx);
  if (error == 0) completed_try_transfers_.fetch_add(1, std::memory_order_relaxed);
  return error;
}

void Bos1901Emulator::reopen() {
  if (unplugged_.load(std::memory_order_relaxed)) {
    throw DeviceError(path_, "open SPI device", ENOENT);
  }
  needs_reopen_ = false;
  reopen_count_.fetch_add(1, std::memory_order_relaxed);
}

}  // namespace vimg
