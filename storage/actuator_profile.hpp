#pragma once
// Actuator profiles (assets/profiles/*.xml): what the hardware is, kept out of the image files.
// Format (docs/hardware.md, "Actuator profiles"):
//   <actuator name="..." type="lra|erm|voice_coil|ideal">
//     <resonance hz="175"/>
//     <response model="lra" q="10"/>             (or bandwidth_hz="17.5"; optional)
//     <response model="erm" spin_up_ms="30" spin_down_ms="45"/>
//     <response model="voice_coil" low_hz="50" high_hz="500"/>
//     <drive rated_voltage_V="1.8" overdrive_clamp_V="2.5" min_pulse_ms="20" braking="true"/>
//     <driver chip="drv2605l|audio|bos1901|hid|none" bus="/dev/i2c-1" address="0x5A">
//       <pin role="enable" gpio="gpiochip0:17"/>
//     </driver>
//   </actuator>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "primitives/actuator/response_params.hpp"

namespace vimg {

enum class ActuatorType { lra, erm, voice_coil, ideal };
enum class DriverChip { drv2605l, audio, bos1901, hid, none };

struct GpioPin {
  std::string chip;      // "gpiochip0"
  unsigned line = 0;     // 17
};

struct ActuatorProfile {
  std::string name;
  ActuatorType type = ActuatorType::ideal;
  double resonance_hz = 175.0;
  // How drive becomes acceleration (docs/actuators.md). Without <response>: the model of `type`
  // with the defaults of ResponseParams; response.resonance_hz is always resonance_hz.
  ResponseParams response;
  double rated_voltage_V = 0.0;      // steady-state drive (RMS) the actuator is rated for
  double overdrive_clamp_V = 0.0;    // peak the driver may reach, e.g. while starting
  double min_pulse_s = 0.0;          // shorter pulses are stretched to this
  bool braking = false;              // active braking when the drive stops
  DriverChip driver = DriverChip::none;
  std::string bus;                   // device node, e.g. "/dev/i2c-1"; empty when not applicable
  int address = -1;                  // I2C address, -1 when not applicable
  std::optional<GpioPin> enable_pin;
  std::optional<GpioPin> trigger_pin;
};

struct ProfileLoadResult {
  std::optional<ActuatorProfile> profile;  // set only when there are no errors
  std::vector<std::string> errors;         // "FILE:LINE: error: problem"
};

// A profile file is small: anything larger is refused before it is read.
inline constexpr std::size_t kMaxProfileFileBytes = 256 * 1024;

ProfileLoadResult parse_actuator_profile(std::string_view xml, const std::string& file_name);
// `argument` is a path, or a shipped profile's bare name ("lra-175hz-drv2605l"), found through
// storage/shipped_data.hpp when no file of that name is in the working folder.
ProfileLoadResult load_actuator_profile(const std::filesystem::path& argument);

// "gpiochip0:17" -> {gpiochip0, 17}; nothing when malformed.
std::optional<GpioPin> parse_gpio_pin(std::string_view text);

std::string_view to_string(ActuatorType type);
std::string_view to_string(ResponseModel model);
std::string_view to_string(DriverChip chip);

}  // namespace vimg
