#pragma once
// Boreas BOS1901 sample streaming over SPI: a DriveSink.
// open(): software reset (CONFIG.RST), CONFIG with PLAY for the sample rate (8..1024 ksps), BC =
// IC_STATUS so that every word returns the FIFO state on SDO, one 0 V sample, then OE.
// write(): each drive sample becomes a 12-bit two's complement REFERENCE word scaled by
// rated_voltage / full_scale_V of the profile; when the FIFO has no space the driver waits on the
// clock for the chip to play samples out: the FIFO paces the renderer (paces_stream()). A block
// whose samples cannot reach the chip (gone, stopped) still takes its duration on the clock.
// Underrun: IC_STATUS.EMPTY while streaming means the chip ran dry holding the last sample; it is
// reported (one event per dry spell) and the stream restarts from a 0 V sample. OVT stops the output.
// close(): a final 0 V sample, wait until the FIFO is EMPTY, then OE off: start and end at 0 V.
//
// Faults (docs/hardware.md, "Faults and reconnection"): on the render thread transient SPI errors
// are retried with backoff; a word that still fails is dropped (reported once per episode); ENODEV,
// or failures_until_gone failed words in a row, mean the device is gone: the driver posts
// device_gone, takes its DeviceLink down and skips output. The device service thread reconnects
// (reconnect(): reopen the spidev node, then the open() sequence) and puts the link up.
//
// Threads:
//   - control thread: construction, open(), close(), destruction, while neither the render thread
//     nor the device service uses the driver;
//   - render thread: write(). It never throws, allocates, locks or reopens; it waits only on the
//     device (FIFO space, retry backoff) and uses the bus only while link() is up;
//   - device service thread: faults() (consumer), device_path(), reconnect() while link() is down;
//   - any thread: underruns(), device_gone().
#include <atomic>
#include <cstddef>
#include <cstdint>

#include "storage/actuator_profile.hpp"
#include "hal/bos1901_registers.hpp"
#include "hal/fault_log.hpp"
#include "hal/transfer_retry.hpp"
#include "hal/serviced_device.hpp"
#include "hal/spi_bus.hpp"
#include "player/drive_sink.hpp"
#include "realtime/clock.hpp"

namespace vimg {

struct Bos1901Options {
  // Output volts at code 2047. The public material gives +-95 V as the output range; that code 2047
  // is exactly 95 V is our assumption (docs/hardware.md, "BOS1901: gaps").
  double full_scale_V = 95.0;
  int max_retries = 3;
  std::int64_t first_backoff_us = 50;
  int failures_until_gone = 20;  // consecutive failed words that mean the device is gone
};

class Bos1901Driver final : public DriveSink, public ServicedDevice {
 public:
  Bos1901Driver(SpiBus& bus, Clock& clock, const ActuatorProfile& profile, Bos1901Options options = {});
  ~Bos1901Driver() override;

  void open(double sample_rate_hz) override;  // throws std::invalid_argument for other rates
  void write(std::span<const float> drive, double block_start_time_s) override;
  void close() override;
  bool paces_stream() const override { return true; }
  // A full FIFO ahead of the sample being written (kFifoDepth samples).
  double output_latency_s() const override { return static_cast<double>(bos1901::kFifoDepth * sample_period_us_) * 1e-6; }

  FaultLog& faults() override { return faults_; }
  const DeviceLink& link() const override { return link_; }
  const std::string& device_path() const override { return bus_.path(); }
  void reconnect() override;

  bool output_stopped() const { return stopped_; }
  bool device_gone() const { return !link_.up(); }
  double gain() const { return gain_; }
  std::uint64_t underruns() const { return underruns_.load(std::memory_order_relaxed); }

 private:
  template <typename Attempt>
  int retry(Attempt&& attempt);            // 0 or the errno of the last attempt
  std::uint16_t send(std::uint16_t word);  // control and service threads: throws after the retries
  void start_stream();                     // the open() sequence; throws
  // Render thread (and close()): false when the word failed (reported) or the device is gone.
  bool exchange(std::uint16_t word, std::uint16_t& sdo) noexcept;
  bool account(int error) noexcept;
  bool push_sample(std::uint16_t code) noexcept;
  void handle_status(std::uint16_t status) noexcept;
  void stop(FaultKind why) noexcept;
  void keep_pace(std::size_t samples) noexcept;  // waits as long as `samples` take to play

  SpiBus& bus_;
  Clock& clock_;
  Bos1901Options options_;
  FaultLog faults_;
  DeviceLink link_;
  double gain_ = 1.0;
  int play_code_ = 0;
  std::int64_t sample_period_us_ = 125;
  bool playing_ = false;  // control thread (open, close), read by the render thread

  // Device state: the chip's configuration and FIFO as we left them. Used by whichever thread holds
  // the link.
  std::uint16_t config_ = 0;
  int known_space_ = 0;
  bool streaming_ = false;
  bool restart_from_zero_ = false;

  // Render thread only (and the control thread in open() and close()).
  TransferAccount transfer_;  // gone: the render thread took the link down and has not seen it up again
  bool stopped_ = false;
  std::int64_t skip_until_us_ = 0;

  std::atomic<std::uint64_t> underruns_{0};
};

}  // namespace vimg
