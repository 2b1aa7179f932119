#pragma once
// Where the player sends its drive, as the user names it on the command line:
//   audio | audio:DEVICE NAME                       SDL2 audio (default or named device)
//   wav:FILE                                        mono float32 WAV file
//   drv2605l:/dev/i2c-1[,en=gpiochip0:17][,addr=0x5A][,calibration=FILE]
//   spi:/dev/spidev0.0[,mode=0][,speed=4000000]     Boreas BOS1901 sample streaming
//   hid:VID:PID                                     USB HID Simple Haptic Controller (hex ids)
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "storage/actuator_profile.hpp"
#include "hal/fault_log.hpp"
#include "player/drive_sink.hpp"

namespace vimg {

struct AudioOutput { std::string device_name; };
struct WavOutput { std::string path; };
struct Drv2605lOutput {
  std::string bus = "/dev/i2c-1";
  std::optional<GpioPin> enable_pin;
  int address = 0x5A;
  std::string calibration_file;
};
struct SpiOutput {
  std::string device;
  std::uint8_t mode = 0;
  std::uint32_t speed_hz = 4'000'000;
};
struct HidOutput {
  std::uint16_t vendor_id = 0;
  std::uint16_t product_id = 0;
};

using OutputSpec = std::variant<AudioOutput, WavOutput, Drv2605lOutput, SpiOutput, HidOutput>;

struct OutputParseResult {
  std::optional<OutputSpec> spec;
  std::string error;  // "--output VALUE: problem"
};
OutputParseResult parse_output_spec(std::string_view text);

// An opened output: the sink and everything it needs (buses, pins, devices), owned together.
// A hardware output also owns its device service thread (hal/device_service.hpp): sink().open()
// starts it after opening the device and sink().close() stops it before putting the device to rest,
// so while the sink plays, fault messages are formatted and a lost device is reconnected off the
// render thread.
// Threads: sink() is used as a DriveSink is (open/close on the control thread, write on the render
// thread); description(), take_messages(), underruns() and device_gone() from the UI thread.
class Output {
 public:
  virtual ~Output() = default;
  virtual DriveSink& sink() = 0;
  virtual std::string description() const = 0;
  // Messages since the last call (faults formatted by the device service, warnings), for the
  // status line and stderr.
  virtual std::vector<std::string> take_messages() { return {}; }
  virtual std::uint64_t underruns() const { return 0; }
  // True while the device is gone and the service is reconnecting it.
  virtual bool device_gone() const { return false; }
  // Runs the actuator's calibration (DRV2605L auto-calibration) and says what it found and where it
  // was stored. Throws std::runtime_error for outputs without one.
  virtual std::string calibrate();
};

// Opens the devices. `profile` gives the actuator (the built-in 175 Hz LRA when it has none for a
// DRV2605L). Throws DeviceError / std::runtime_error with a message naming the device.
std::unique_ptr<Output> open_output(const OutputSpec& spec, const ActuatorProfile& profile);

// The generic 175 Hz LRA, for when no profile is given: the shipped assets/profiles/lra-175hz-drv2605l.xml
// (found through storage/shipped_data.hpp, read once). Throws std::runtime_error, with the reader's
// messages, when the shipped data cannot be found or read.
inline constexpr const char* kDefaultLraProfileName = "lra-175hz-drv2605l";
ActuatorProfile default_lra_profile();

}  // namespace vimg
