#include "cli/compare_inputs.hpp"

#include <cstdio>

#include "storage/actuator_profile.hpp"
#include "storage/number_text.hpp"
#include "storage/print_diagnostics.hpp"

namespace vimg::cli {

namespace {

// "lra, 175 Hz, Q 10": what of the response shapes the felt signal.
std::string response_text(const ResponseParams& r) {
  std::string text = std::string(to_string(r.model)) + ", " + format_decimal(r.resonance_hz) + " Hz";
  if (r.model == ResponseModel::lra) text += ", Q " + format_decimal(r.q);
  if (r.model == ResponseModel::voice_coil) text += ", " + format_decimal(r.low_hz) + "-" + format_decimal(r.high_hz) + " Hz";
  if (r.model == ResponseModel::erm)
    text += ", spin-up " + format_decimal(r.spin_up_s) + " s, spin-down " + format_decimal(r.spin_down_s) + " s";
  return text;
}

bool same_response(const ResponseParams& a, const ResponseParams& b) {
  return a.model == b.model && a.resonance_hz == b.resonance_hz && a.q == b.q && a.low_hz == b.low_hz &&
         a.high_hz == b.high_hz && a.spin_up_s == b.spin_up_s && a.spin_down_s == b.spin_down_s;
}

std::string given_text(const study::CompareActuator& a) { return a.file.empty() ? a.name : a.file; }

}  // namespace

std::optional<study::CompareActuator> load_compare_actuator(const std::string& argument) {
  study::CompareActuator actuator;
  if (argument.empty()) return actuator;
  const ProfileLoadResult loaded = load_actuator_profile(argument);
  for (const std::string& e : loaded.errors) std::fprintf(stderr, "%s\n", e.c_str());
  if (!loaded.profile) return std::nullopt;
  actuator.name = loaded.profile->name.empty() ? argument : loaded.profile->name;
  actuator.file = argument;
  actuator.response = loaded.profile->response;
  return actuator;
}

std::optional<std::string> model_actuator_mismatch(const PerceptionModel& model, const study::CompareActuator& actuator) {
  const ModelActuator& fitted = model.actuator;
  if (!fitted.response || same_response(*fitted.response, actuator.response)) return std::nullopt;
  const std::string name = fitted.name.empty() ? fitted.given : fitted.name;
  return "the model was fitted through the actuator '" + name + "' (" + response_text(*fitted.response) +
         "), and the images are felt here through '" + actuator.name + "' (" + response_text(actuator.response) +
         "): its weights hold for what the participants felt; give --actuator " + fitted.given +
         ", or fit a model on trials felt through this actuator";
}

std::optional<PerceptionModel> load_model_argument(const std::string& file, const study::CompareActuator& actuator) {
  PerceptionModelLoadResult loaded = load_perception_model(file);
  if (loaded.model) {
    const ModelActuator& fitted = loaded.model->actuator;
    if (const auto why = model_actuator_mismatch(*loaded.model, actuator)) {
      loaded.diagnostics.push_back({Diagnostic::Severity::error, file, fitted.line, *why});
      print_diagnostics(loaded.diagnostics);
      return std::nullopt;
    }
    if (!fitted.response && fitted.given != given_text(actuator) && fitted.given != actuator.name) {
      const std::string named = fitted.given.empty() ? "does not name the actuator it was fitted through"
                                                     : "names the actuator '" + fitted.given + "' but not its response";
      loaded.diagnostics.push_back({Diagnostic::Severity::warning, file, fitted.line,
                                    "the model " + named + " (a model of an older vimg, or written by hand), so it cannot be "
                                    "checked against the actuator '" + actuator.name + "' given here; its weights hold only "
                                    "for the actuator the participants felt"});
    }
  }
  print_diagnostics(loaded.diagnostics);
  return std::move(loaded.model);
}

}  // namespace vimg::cli
