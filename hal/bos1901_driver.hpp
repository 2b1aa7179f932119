#pragma once
// Boreas BOS1901 sample streaming over SPI: a DriveSink.
// open(): software reset (CONFIG.RST), CONFIG with PLAY for the sample rate (8..1024 ksps), BC =
// IC_STATUS so that every word returns the FIFO state on SDO, one 0 V sample, then OE.
// write(): each drive sample becomes a 12-bit two's complement REFERENCE word scaled by
// rated_voltage / full_scale_V of the profile; when the FIFO has no space the driver waits on the
// clock for the chip to play samples out (the FIFO paces the renderer).
// Underrun: IC_STATUS.EMPTY while streaming means the chip ran dry holding the last sample; it is
// reported (one event per dry spell) and the stream restarts from a 0 V sample. OVT stops the output.
// close(): a final 0 V sample, wait until the FIFO is EMPTY, then OE off: start and end at 0 V.
#include <atomic>
#include <cstdint>

#include "hal/actuator_profile.hpp"
#include "realtime/clock.hpp"
#include "hal/fault_log.hpp"
#include "hal/spi_bus.hpp"
#include "player/drive_sink.hpp"

namespace vimg {

struct Bos1901Options {
  // Output volts at code 2047. The public material gives +-95 V as the output range; that code 2047
  // is exactly 95 V is our assumption (docs/hardware.md, "BOS1901: gaps").
  double full_scale_V = 95.0;
  int max_retries = 3;
  std::int64_t first_backoff_us = 50;
};

class Bos1901Driver final : public DriveSink {
 public:
  Bos1901Driver(SpiBus& bus, Clock& clock, const ActuatorProfile& profile, Bos1901Options options = {});
  ~Bos1901Driver() override;

  void open(double sample_rate_hz) override;  // throws std::invalid_argument for other rates
  void write(std::span<const float> drive, double block_start_time_s) override;
  void close() override;

  FaultLog& faults() { return faults_; }
  bool output_stopped() const { return stopped_; }
  double gain() const { return gain_; }
  std::uint64_t underruns() const { return underruns_.load(std::memory_order_relaxed); }

 private:
  std::uint16_t send(std::uint16_t word);  // returns SDO; retries transient errors, then throws
  void push_sample(std::uint16_t code);
  void handle_status(std::uint16_t status);
  void stop(FaultKind why);

  SpiBus& bus_;
  Clock& clock_;
  Bos1901Options options_;
  FaultLog faults_;
  double gain_ = 1.0;
  std::uint16_t config_ = 0;
  std::int64_t sample_period_us_ = 125;
  int known_space_ = 0;
  bool playing_ = false;
  bool stopped_ = false;
  bool streaming_ = false;
  bool restart_from_zero_ = false;
  std::atomic<std::uint64_t> underruns_{0};
};

}  // namespace vimg
