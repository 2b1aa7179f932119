#include "hal/output_spec.hpp"

#include "storage/atomic_file.hpp"

#include <charconv>
#include <cstdio>
#include <stdexcept>

#include "hal/bos1901_driver.hpp"
#include "hal/device_service.hpp"
#include "hal/drv2605l_driver.hpp"
#include "hal/hid_haptic_controller.hpp"
#include "hal/sdl_audio_sink.hpp"
#include "player/drive_sinks.hpp"
#include "realtime/clock.hpp"

namespace vimg {

namespace {

template <typename Number>
bool parse_number(std::string_view text, Number& value, int base = 10) {
  if (base == 16 && (text.starts_with("0x") || text.starts_with("0X"))) text.remove_prefix(2);
  if (base == 0) {
    base = 10;
    if (text.starts_with("0x") || text.starts_with("0X")) {
      text.remove_prefix(2);
      base = 16;
    }
  }
  const auto [end, status] = std::from_chars(text.data(), text.data() + text.size(), value, base);
  return !text.empty() && status == std::errc() && end == text.data() + text.size();
}

std::vector<std::string_view> split(std::string_view text, char separator) {
  std::vector<std::string_view> parts;
  while (true) {
    const auto at = text.find(separator);
    parts.push_back(text.substr(0, at));
    if (at == std::string_view::npos) break;
    text.remove_prefix(at + 1);
  }
  return parts;
}

OutputParseResult failure(std::string_view text, const std::string& problem) {
  return {std::nullopt, "--output " + std::string(text) + ": " + problem};
}

}  // namespace

OutputParseResult parse_output_spec(std::string_view text) {
  const auto colon = text.find(':');
  const std::string_view kind = text.substr(0, colon);
  const std::string_view rest = colon == std::string_view::npos ? std::string_view{} : text.substr(colon + 1);
  if (kind == "audio") {
    return {AudioOutput{std::string(rest)}, {}};
  }
  if (kind == "wav") {
    if (rest.empty()) return failure(text, "needs a file name: wav:FILE");
    return {WavOutput{std::string(rest)}, {}};
  }
  if (kind == "drv2605l") {
    const auto parts = split(rest, ',');
    Drv2605lOutput output;
    if (parts[0].empty()) return failure(text, "needs the I2C adapter: drv2605l:/dev/i2c-1[,en=gpiochip0:17]");
    output.bus = std::string(parts[0]);
    for (std::size_t i = 1; i < parts.size(); ++i) {
      const auto equals = parts[i].find('=');
      const auto key = parts[i].substr(0, equals);
      const auto value = equals == std::string_view::npos ? std::string_view{} : parts[i].substr(equals + 1);
      if (key == "en") {
        output.enable_pin = parse_gpio_pin(value);
        if (!output.enable_pin) return failure(text, "en must look like gpiochip0:17");
      } else if (key == "addr") {
        if (!parse_number(value, output.address, 0) || output.address < 0 || output.address > 0x7F) {
          return failure(text, "addr must be a 7-bit I2C address");
        }
      } else if (key == "calibration") {
        output.calibration_file = std::string(value);
      } else {
        return failure(text, "unknown option '" + std::string(key) + "' (en, addr, calibration)");
      }
    }
    return {output, {}};
  }
  if (kind == "spi") {
    const auto parts = split(rest, ',');
    SpiOutput output;
    if (parts[0].empty()) return failure(text, "needs the SPI device: spi:/dev/spidev0.0");
    output.device = std::string(parts[0]);
    for (std::size_t i = 1; i < parts.size(); ++i) {
      const auto equals = parts[i].find('=');
      const auto key = parts[i].substr(0, equals);
      const auto value = equals == std::string_view::npos ? std::string_view{} : parts[i].substr(equals + 1);
      unsigned number = 0;
      if (key == "mode" && parse_number(value, number) && number <= 3) {
        output.mode = static_cast<std::uint8_t>(number);
      } else if (key == "speed" && parse_number(value, number) && number > 0) {
        output.speed_hz = number;
      } else {
        return failure(text, "bad option '" + std::string(parts[i]) + "' (mode=0..3, speed=HZ)");
      }
    }
    return {output, {}};
  }
  if (kind == "hid") {
    const auto parts = split(rest, ':');
    HidOutput output;
    if (parts.size() != 2 || !parse_number(parts[0], output.vendor_id, 16) ||
        !parse_number(parts[1], output.product_id, 16)) {
      return failure(text, "needs hexadecimal ids: hid:VID:PID, e.g. hid:1234:5678");
    }
    return {output, {}};
  }
  return failure(text, "unknown output; use audio, wav:FILE, drv2605l:BUS[,en=CHIP:LINE], spi:DEVICE or hid:VID:PID");
}

ActuatorProfile default_lra_profile() {
  // Read once from the shipped data: the XML is the one definition of this actuator.
  static const ProfileLoadResult shipped = load_actuator_profile(kDefaultLraProfileName);
  if (!shipped.profile) {
    std::string message = "the shipped profile " + std::string(kDefaultLraProfileName) + " cannot be read";
    for (const std::string& e : shipped.errors) message += "\n" + e;
    throw std::runtime_error(message);
  }
  return *shipped.profile;
}

std::string Output::calibrate() {
  throw std::runtime_error(description() + ": this output has no calibration");
}

namespace {

// A driver's sink with its device service running while it plays: started after open(), stopped
// before close(), so that the service never reconnects while the control thread opens or closes
// the device.
class ServicedSink final : public DriveSink {
 public:
  ServicedSink(DriveSink& sink, ServicedDevice& device, DeviceService& service) : sink_(sink), service_(service) {
    service_.add(device);
  }
  void open(double sample_rate_hz) override {
    sink_.open(sample_rate_hz);
    service_.start();
  }
  void write(std::span<const float> drive, double block_start_time_s) override {
    sink_.write(drive, block_start_time_s);
  }
  void close() override {
    service_.stop();
    sink_.close();
  }
  bool paces_stream() const override { return sink_.paces_stream(); }
  std::size_t min_block_samples() const override { return sink_.min_block_samples(); }

 private:
  DriveSink& sink_;
  DeviceService& service_;
};

class AudioOut final : public Output {
 public:
  explicit AudioOut(const AudioOutput& spec) : name_(spec.device_name) {
    SdlAudioOptions options;
    options.device_name = spec.device_name;
    sink_ = std::make_unique<SdlAudioSink>(options);
  }
  DriveSink& sink() override { return *sink_; }
  std::string description() const override { return "audio " + (name_.empty() ? std::string("(default)") : name_); }
  std::uint64_t underruns() const override { return sink_->underruns(); }

 private:
  std::string name_;
  std::unique_ptr<SdlAudioSink> sink_;
};

class WavOut final : public Output {
 public:
  // A file that cannot be written is an error now, before anything plays (std::runtime_error).
  explicit WavOut(const WavOutput& spec) : path_(spec.path), sink_(spec.path) {
    AtomicFileWriter probe(path_);  // the same create as the sink's, abandoned at once
    if (!probe.ok()) throw std::runtime_error(probe.error());
  }
  DriveSink& sink() override { return sink_; }
  std::string description() const override { return "wav " + path_; }
  std::vector<std::string> take_messages() override {
    if (sink_.error() && !reported_) {
      reported_ = true;
      return {*sink_.error()};
    }
    return {};
  }

 private:
  std::string path_;
  WavSink sink_;
  bool reported_ = false;
};

class Drv2605lOut final : public Output {
 public:
  Drv2605lOut(const Drv2605lOutput& spec, const ActuatorProfile& given)
      : bus_(spec.bus), calibration_file_(spec.calibration_file) {
    ActuatorProfile profile = given.type == ActuatorType::lra ? given : default_lra_profile();
    profile.address = spec.address;
    if (spec.enable_pin) {
      pin_ = std::make_unique<GpiodOutput>(spec.enable_pin->chip, spec.enable_pin->line, "vimg-player", false);
    }
    Drv2605lOptions options;
    options.calibration_file = spec.calibration_file;
    driver_ = std::make_unique<Drv2605lDriver>(bus_, pin_.get(), clock_, profile, options);
    driver_->initialize();
    startup_warning_ = driver_->calibration_warning();  // read here: later the render thread owns the driver
    sink_ = std::make_unique<ServicedSink>(*driver_, *driver_, service_);
  }
  DriveSink& sink() override { return *sink_; }
  std::string description() const override { return "drv2605l " + bus_.path(); }
  std::vector<std::string> take_messages() override {
    auto messages = service_.take_messages();
    if (startup_warning_) {
      messages.push_back(*startup_warning_);
      startup_warning_.reset();
    }
    return messages;
  }
  bool device_gone() const override { return driver_->device_gone(); }
  std::string calibrate() override {
    const Drv2605lCalibration result = driver_->calibrate();
    char text[200];
    std::snprintf(text, sizeof text, "A_CAL_COMP=0x%02X A_CAL_BEMF=0x%02X BEMF_GAIN=%u", result.a_cal_comp,
                  result.a_cal_bemf, static_cast<unsigned>(result.bemf_gain));
    return bus_.path() + ": auto-calibration done: " + text +
           (calibration_file_.empty() ? std::string("; not stored (add ,calibration=FILE to --output)")
                                      : "; stored in " + calibration_file_);
  }

 private:
  LinuxI2cBus bus_;
  std::string calibration_file_;
  SystemClock clock_;
  std::unique_ptr<GpiodOutput> pin_;
  std::unique_ptr<Drv2605lDriver> driver_;
  DeviceService service_;  // declared after the driver: stopped before the driver closes
  std::unique_ptr<ServicedSink> sink_;
  std::optional<std::string> startup_warning_;
};

class SpiOut final : public Output {
 public:
  SpiOut(const SpiOutput& spec, const ActuatorProfile& profile)
      : bus_(spec.device, SpiSettings{spec.mode, spec.speed_hz, 8}),
        driver_(bus_, clock_, profile),
        sink_(driver_, driver_, service_) {}
  DriveSink& sink() override { return sink_; }
  std::string description() const override { return "bos1901 " + bus_.path(); }
  std::vector<std::string> take_messages() override { return service_.take_messages(); }
  std::uint64_t underruns() const override { return driver_.underruns(); }
  bool device_gone() const override { return driver_.device_gone(); }

 private:
  LinuxSpiBus bus_;
  SystemClock clock_;
  Bos1901Driver driver_;
  DeviceService service_;  // declared after the driver: stopped before the driver closes
  ServicedSink sink_;
};

class HidOut final : public Output {
 public:
  HidOut(const HidOutput& spec, const ActuatorProfile& profile) {
    HidHapticOptions options;
    options.resonance_hz = profile.resonance_hz;
    controller_ = std::make_unique<HidHapticController>(host_, spec.vendor_id, spec.product_id, clock_, options);
    controller_->connect();
    description_ = "hid " + controller_->device_path();  // the path may change when it reconnects
    sink_ = std::make_unique<ServicedSink>(*controller_, *controller_, service_);
  }
  DriveSink& sink() override { return *sink_; }
  std::string description() const override { return description_; }
  std::vector<std::string> take_messages() override { return service_.take_messages(); }
  bool device_gone() const override { return controller_->device_gone(); }

 private:
  HidapiHost host_;
  SystemClock clock_;
  std::unique_ptr<HidHapticController> controller_;
  DeviceService service_;  // declared after the controller: stopped before it closes
  std::unique_ptr<ServicedSink> sink_;
  std::string description_;
};

}  // namespace

std::unique_ptr<Output> open_output(const OutputSpec& spec, const ActuatorProfile& profile) {
  return std::visit(
      [&](const auto& chosen) -> std::unique_ptr<Output> {
        using T = std::decay_t<decltype(chosen)>;
        if constexpr (std::is_same_v<T, AudioOutput>) return std::make_unique<AudioOut>(chosen);
        if constexpr (std::is_same_v<T, WavOutput>) return std::make_unique<WavOut>(chosen);
        if constexpr (std::is_same_v<T, Drv2605lOutput>) return std::make_unique<Drv2605lOut>(chosen, profile);
        if constexpr (std::is_same_v<T, SpiOutput>) return std::make_unique<SpiOut>(chosen, profile);
        if constexpr (std::is_same_v<T, HidOutput>) return std::make_unique<HidOut>(chosen, profile);
      },
      spec);
}

}  // namespace vimg
