#pragma once
// One GPIO output line (a driver's EN or trigger pin). Real: GpiodOutput (libgpiod 1.6).
// Test double: RecordingGpioOutput, or the pin an emulator exposes (Drv2605lEmulator::enable_pin()).
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

struct gpiod_chip;
struct gpiod_line;

namespace vimg {

class GpioOutput {
 public:
  virtual ~GpioOutput() = default;
  virtual void set(bool high) = 0;  // throws DeviceError
  virtual const std::string& name() const = 0;
};

// gpiod_chip_open_by_name(chip) / gpiod_chip_get_line / gpiod_line_request_output.
class GpiodOutput final : public GpioOutput {
 public:
  GpiodOutput(const std::string& chip_name, unsigned line_offset, const std::string& consumer,
              bool initial_high);
  ~GpiodOutput() override;  // releases the line; the kernel keeps its last value
  GpiodOutput(const GpiodOutput&) = delete;
  GpiodOutput& operator=(const GpiodOutput&) = delete;

  void set(bool high) override;
  const std::string& name() const override { return name_; }

 private:
  std::string name_;  // "gpiochip0:17"
  gpiod_chip* chip_ = nullptr;
  gpiod_line* line_ = nullptr;
};

// Test double: records every level with the time given by `now_us`.
class RecordingGpioOutput final : public GpioOutput {
 public:
  struct Change {
    std::int64_t time_us;
    bool high;
  };
  explicit RecordingGpioOutput(std::function<std::int64_t()> now_us, std::string name = "gpio-emulated")
      : now_us_(std::move(now_us)), name_(std::move(name)) {}
  void set(bool high) override { changes_.push_back({now_us_(), high}); }
  const std::string& name() const override { return name_; }
  const std::vector<Change>& changes() const { return changes_; }

 private:
  std::function<std::int64_t()> now_us_;
  std::string name_;
  std::vector<Change> changes_;
};

}  // namespace vimg
