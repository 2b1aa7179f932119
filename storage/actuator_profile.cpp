#include "storage/actuator_profile.hpp"

#include "storage/diagnostic.hpp"
#include "storage/read_file.hpp"
#include "storage/shipped_data.hpp"
#include "storage/xml_attributes.hpp"
#include "storage/xml_limits.hpp"
#include "storage/xml_parse_problem.hpp"

#include <tinyxml2.h>

#include <charconv>
#include <cmath>

namespace vimg {

namespace {

class ProfileParser {
 public:
  explicit ProfileParser(const std::string& file_name) : list_(file_name), attributes_(list_) {}

  void error(int line, const std::string& problem) { list_.error(line, problem); }
  static std::string q(std::string_view input) { return escape_input(input); }

  // A number attribute in [min_value, max_value] (storage/xml_attributes.hpp: the one grammar and
  // wording of every XML reader); nothing when absent or malformed (reported).
  std::optional<double> number(const tinyxml2::XMLElement& element, const char* attribute, bool required,
                               double min_value, double max_value) {
    return attributes_.number(element, attribute, NumberRange::closed(min_value, max_value), required);
  }

  std::optional<bool> boolean(const tinyxml2::XMLElement& element, const char* attribute) {
    return attributes_.boolean(element, attribute);
  }

  ProfileLoadResult parse(std::string_view xml) {
    // Structure limits first: tinyxml2 is quadratic in attributes (storage/xml_limits.hpp).
    if (const auto over = check_xml_limits(xml)) {
      error(over->line, over->message);
      return finish(std::nullopt);
    }
    tinyxml2::XMLDocument document;
    if (document.Parse(xml.data(), xml.size()) != tinyxml2::XML_SUCCESS) {
      error(document.ErrorLineNum(), xml_parse_problem(document.ErrorID()));
      return finish(std::nullopt);
    }
    const tinyxml2::XMLElement* root = document.RootElement();
    if (root == nullptr || std::string_view(root->Name()) != "actuator") {
      error(root != nullptr ? root->GetLineNum() : 1, "the root element must be <actuator>");
      return finish(std::nullopt);
    }
    ActuatorProfile profile;
    const tinyxml2::XMLElement* response = nullptr;
    if (const char* name = root->Attribute("name")) {
      profile.name = name;
    } else {
      error(root->GetLineNum(), "<actuator> needs attribute 'name'");
    }
    const std::string type = root->Attribute("type") != nullptr ? root->Attribute("type") : "";
    if (type == "lra") profile.type = ActuatorType::lra;
    else if (type == "erm") profile.type = ActuatorType::erm;
    else if (type == "voice_coil") profile.type = ActuatorType::voice_coil;
    else if (type == "ideal") profile.type = ActuatorType::ideal;
    else error(root->GetLineNum(), "<actuator> type must be lra, erm, voice_coil or ideal, not '" + q(type) + "'");

    for (const tinyxml2::XMLElement* child = root->FirstChildElement(); child != nullptr;
         child = child->NextSiblingElement()) {
      const std::string_view name = child->Name();
      if (name == "resonance") {
        if (auto hz = number(*child, "hz", true, 1.0, 20000.0)) profile.resonance_hz = *hz;
      } else if (name == "drive") {
        if (auto v = number(*child, "rated_voltage_V", false, 0.0, 100.0)) profile.rated_voltage_V = *v;
        if (auto v = number(*child, "overdrive_clamp_V", false, 0.0, 100.0)) profile.overdrive_clamp_V = *v;
        if (auto ms = number(*child, "min_pulse_ms", false, 0.0, 1000.0)) profile.min_pulse_s = *ms / 1000.0;
        if (auto b = boolean(*child, "braking")) profile.braking = *b;
        if (profile.overdrive_clamp_V > 0.0 && profile.overdrive_clamp_V < profile.rated_voltage_V) {
          error(child->GetLineNum(), "overdrive_clamp_V must not be below rated_voltage_V");
        }
      } else if (name == "driver") {
        parse_driver(*child, profile);
      } else if (name == "response") {
        if (response != nullptr) error(child->GetLineNum(), "<actuator> has more than one <response>");
        response = child;
      } else {
        error(child->GetLineNum(), "unknown element <" + q(name) + "> in <actuator>");
      }
    }
    parse_response(response, profile);
    if (profile.driver == DriverChip::drv2605l && profile.rated_voltage_V <= 0.0) {
      error(root->GetLineNum(), "a drv2605l actuator needs <drive rated_voltage_V=...> above 0");
    }
    return finish(profile);
  }

 private:
  // <response>, after the whole <actuator> is read (it needs the type and the resonance).
  void parse_response(const tinyxml2::XMLElement* element, ActuatorProfile& profile) {
    ResponseParams& r = profile.response;
    r.resonance_hz = profile.resonance_hz;
    switch (profile.type) {
      case ActuatorType::lra: r.model = ResponseModel::lra; break;
      case ActuatorType::erm: r.model = ResponseModel::erm; break;
      case ActuatorType::voice_coil: r.model = ResponseModel::voice_coil; break;
      case ActuatorType::ideal: r.model = ResponseModel::ideal; break;
    }
    if (element == nullptr) return;
    const int line = element->GetLineNum();
    if (const char* model = element->Attribute("model")) {
      const std::string_view text = model;
      if (text == "lra") r.model = ResponseModel::lra;
      else if (text == "erm") r.model = ResponseModel::erm;
      else if (text == "voice_coil") r.model = ResponseModel::voice_coil;
      else if (text == "ideal") r.model = ResponseModel::ideal;
      else error(line, "<response> model must be lra, erm, voice_coil or ideal, not '" + escape_input(text) + "'");
    }
    for (const tinyxml2::XMLAttribute* a = element->FirstAttribute(); a != nullptr; a = a->Next()) {
      const std::string_view name = a->Name();
      const bool known = name == "model" || (r.model == ResponseModel::lra && (name == "q" || name == "bandwidth_hz")) ||
                         (r.model == ResponseModel::erm && (name == "spin_up_ms" || name == "spin_down_ms")) ||
                         (r.model == ResponseModel::voice_coil && (name == "low_hz" || name == "high_hz"));
      if (!known) {
        error(line, "attribute '" + escape_input(name) + "' does not belong to <response model=\"" +
                        std::string(to_string(r.model)) + "\">");
      }
    }
    switch (r.model) {
      case ResponseModel::ideal:
        break;
      case ResponseModel::lra: {
        const auto q = number(*element, "q", false, kMinResponseQ, kMaxResponseQ);
        const auto bandwidth = number(*element, "bandwidth_hz", false, r.resonance_hz / kMaxResponseQ,
                                      r.resonance_hz / kMinResponseQ);
        if (element->Attribute("q") != nullptr && element->Attribute("bandwidth_hz") != nullptr) {
          error(line, "<response> gives q or bandwidth_hz, not both");
        }
        if (q) r.q = *q;
        if (bandwidth) r.q = r.resonance_hz / *bandwidth;
        break;
      }
      case ResponseModel::erm:
        if (auto ms = number(*element, "spin_up_ms", false, kMinSpinTimeS * 1000.0, kMaxSpinTimeS * 1000.0)) r.spin_up_s = *ms / 1000.0;
        if (auto ms = number(*element, "spin_down_ms", false, kMinSpinTimeS * 1000.0, kMaxSpinTimeS * 1000.0)) r.spin_down_s = *ms / 1000.0;
        break;
      case ResponseModel::voice_coil: {
        const auto low = number(*element, "low_hz", false, kMinCornerHz, kMaxCornerHz);
        const auto high = number(*element, "high_hz", false, kMinCornerHz, kMaxCornerHz);
        if (low) r.low_hz = *low;
        if (high) r.high_hz = *high;
        if (r.low_hz >= r.high_hz) error(line, "<response> low_hz must be below high_hz");
        break;
      }
    }
  }

  void parse_driver(const tinyxml2::XMLElement& element, ActuatorProfile& profile) {
    const std::string chip = element.Attribute("chip") != nullptr ? element.Attribute("chip") : "";
    if (chip == "drv2605l") profile.driver = DriverChip::drv2605l;
    else if (chip == "audio") profile.driver = DriverChip::audio;
    else if (chip == "bos1901") profile.driver = DriverChip::bos1901;
    else if (chip == "hid") profile.driver = DriverChip::hid;
    else if (chip == "none") profile.driver = DriverChip::none;
    else error(element.GetLineNum(), "<driver> chip must be drv2605l, audio, bos1901, hid or none, not '" + q(chip) + "'");
    if (const char* bus = element.Attribute("bus")) profile.bus = bus;
    if (const char* address = element.Attribute("address")) {
      std::string_view text = address;
      int base = 10;
      if (text.starts_with("0x") || text.starts_with("0X")) {
        text.remove_prefix(2);
        base = 16;
      }
      int value = -1;
      const auto [end, status] = std::from_chars(text.data(), text.data() + text.size(), value, base);
      if (status != std::errc() || end != text.data() + text.size() || value < 0 || value > 0x7F) {
        error(element.GetLineNum(), "<driver> address must be a 7-bit I2C address, not '" + q(address) + "'");
      } else {
        profile.address = value;
      }
    }
    for (const tinyxml2::XMLElement* pin = element.FirstChildElement(); pin != nullptr;
         pin = pin->NextSiblingElement()) {
      if (std::string_view(pin->Name()) != "pin") {
        error(pin->GetLineNum(), "unknown element <" + q(pin->Name()) + "> in <driver>");
        continue;
      }
      const std::string role = pin->Attribute("role") != nullptr ? pin->Attribute("role") : "";
      const char* gpio_text = pin->Attribute("gpio");
      const auto gpio = gpio_text != nullptr ? parse_gpio_pin(gpio_text) : std::nullopt;
      if (!gpio) {
        error(pin->GetLineNum(), "<pin> gpio must look like gpiochip0:17");
        continue;
      }
      if (role == "enable") profile.enable_pin = gpio;
      else if (role == "trigger") profile.trigger_pin = gpio;
      else error(pin->GetLineNum(), "<pin> role must be enable or trigger, not '" + q(role) + "'");
    }
  }

  ProfileLoadResult finish(std::optional<ActuatorProfile> profile) {
    ProfileLoadResult result;
    for (const Diagnostic& d : list_.take()) result.errors.push_back(d.to_string());
    if (result.errors.empty()) {
      result.profile = std::move(profile);
    }
    return result;
  }

  DiagnosticList list_;
  XmlAttributes attributes_;
};

}  // namespace

std::optional<GpioPin> parse_gpio_pin(std::string_view text) {
  const auto colon = text.rfind(':');
  if (colon == std::string_view::npos || colon == 0 || colon + 1 == text.size()) {
    return std::nullopt;
  }
  GpioPin pin;
  pin.chip = std::string(text.substr(0, colon));
  const std::string_view number = text.substr(colon + 1);
  const auto [end, status] = std::from_chars(number.data(), number.data() + number.size(), pin.line);
  if (status != std::errc() || end != number.data() + number.size()) {
    return std::nullopt;
  }
  return pin;
}

ProfileLoadResult parse_actuator_profile(std::string_view xml, const std::string& file_name) {
  return ProfileParser(file_name).parse(xml);
}

ProfileLoadResult load_actuator_profile(const std::filesystem::path& argument) {
  const std::filesystem::path path = resolve_profile_argument(argument);
  FileReadResult read = read_regular_file(path, kMaxProfileFileBytes);
  if (!read.bytes) {
    ProfileLoadResult result;
    std::string problem = read.error;
    if (path == argument && !argument.has_parent_path() && !argument.has_extension()) {
      const std::vector<std::string> shipped = shipped_profile_names();
      problem += shipped.empty() ? "; " + shipped_data_help() : "; not a shipped profile either (shipped:";
      for (const std::string& name : shipped) problem += " " + name;
      if (!shipped.empty()) problem += ")";
    }
    result.errors.push_back(path.string() + ": error: " + problem);
    return result;
  }
  return parse_actuator_profile(*read.bytes, path.string());
}

std::string_view to_string(ActuatorType type) {
  switch (type) {
    case ActuatorType::lra: return "lra";
    case ActuatorType::erm: return "erm";
    case ActuatorType::voice_coil: return "voice_coil";
    case ActuatorType::ideal: return "ideal";
  }
  return "ideal";
}

std::string_view to_string(ResponseModel model) {
  switch (model) {
    case ResponseModel::lra: return "lra";
    case ResponseModel::erm: return "erm";
    case ResponseModel::voice_coil: return "voice_coil";
    case ResponseModel::ideal: return "ideal";
  }
  return "ideal";
}

std::string_view to_string(DriverChip chip) {
  switch (chip) {
    case DriverChip::drv2605l: return "drv2605l";
    case DriverChip::audio: return "audio";
    case DriverChip::bos1901: return "bos1901";
    case DriverChip::hid: return "hid";
    case DriverChip::none: return "none";
  }
  return "none";
}

}  // namespace vimg
