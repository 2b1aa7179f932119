#include "cli/felt_report.hpp"

#include <cmath>
#include <cstdio>

#include "primitives/actuator/primitive_frequencies.hpp"

namespace vimg::cli {

namespace {

std::string format_db(double db) {
  char text[32];
  // No "-0.0": a response within 0.05 dB of the peak is shown as 0.0.
  std::snprintf(text, sizeof text, "%.1f", db < -999.0 ? -999.0 : (db > -0.05 ? 0.0 : db));
  return text;
}

std::string format_mm(double mm) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", mm);
  return text;
}

std::string band_text(const FrequencyBand& band) {
  return format_hz(band.low_hz) + "-" + format_hz(band.high_hz) + " Hz";
}

std::string name_of(const PrimitiveFrequency& p) {
  return std::string(p.kind) + (p.element->id.empty() ? "" : " '" + escape_input(p.element->id) + "'");
}

}  // namespace

std::string format_hz(double frequency_hz) {
  char text[32];
  std::snprintf(text, sizeof text, frequency_hz >= 100.0 ? "%.0f" : "%.3g", frequency_hz);
  return text;
}

std::string FeltAnalysis::describe() const {
  const std::string peak = band_.peak_hz() > 0.0 ? " at " + format_hz(band_.peak_hz()) + " Hz" : " at 0 Hz";
  return escape_input(profile_.name) + " (" + std::string(to_string(profile_.response.model)) + ", felt band " +
         band_text(band_.felt()) + ": within " + format_hz(kFeltWithinDb) + " dB of the peak" + peak + ")";
}

std::unique_ptr<FeltAnalysis> load_felt_analysis(const std::string& profile_path) {
  ProfileLoadResult loaded = load_actuator_profile(profile_path);
  for (const std::string& e : loaded.errors) std::fprintf(stderr, "%s\n", e.c_str());
  if (!loaded.profile) return nullptr;
  return std::make_unique<FeltAnalysis>(std::move(*loaded.profile));
}

void add_felt_warnings(const Image& image, const FeltAnalysis& analysis, DiagnosticList& out) {
  const double full_speed = image.effective_interaction().full_speed_mm_per_s;
  for (const PrimitiveFrequency& p : primitive_frequencies(image, analysis.profile().resonance_hz)) {
    if (p.kind == "dot") continue;  // a DOT plays at the actuator's own carrier
    const FeltCheck c = analysis.band().check(p.frequency_hz);
    if (!c.weak) continue;
    const int line = p.element->source_line;
    if (!out.keeps(line)) {
      out.count(Diagnostic::Severity::warning);
      continue;
    }
    std::string message = name_of(p) + " at " + format_hz(p.frequency_hz) + " Hz";
    std::string suggestion;
    if (const auto* surface = std::get_if<Surface>(&p.element->body)) {
      message += " (fullSpeed " + format_hz(full_speed) + " mm/s / period " + format_mm(surface->period_mm) + " mm)";
      suggestion = "a period of " + format_mm(full_speed / c.suggested_frequency_hz) + " mm (" +
                   format_hz(c.suggested_frequency_hz) + " Hz) would be felt";
    } else {
      suggestion = "a frequency of " + format_hz(c.suggested_frequency_hz) + " Hz would be felt";
    }
    message += " is " + format_db(c.response_db) + " dB on actuator '" + escape_input(analysis.profile().name) +
               "', outside its felt band " + band_text(analysis.band().felt()) + " (within " +
               format_hz(kFeltWithinDb) + " dB of the peak); " + suggestion;
    out.warning(line, message);
  }
}

void print_felt_table(const Image& image, const FeltAnalysis& analysis) {
  std::printf("%-13s %s\n", "actuator:", analysis.describe().c_str());
  std::printf("  %6s  %-32s %10s %10s\n", "line", "primitive", "freq_Hz", "resp_dB");
  const bool erm = analysis.profile().response.model == ResponseModel::erm;
  for (const PrimitiveFrequency& p : primitive_frequencies(image, analysis.profile().resonance_hz)) {
    if (erm && p.kind == "dot") {
      // A DOT on an ERM is the motor's own vibration, not a modulation of it.
      std::printf("  %6d  %-32s %10s %10s  (the motor's own vibration)\n", p.element->source_line, name_of(p).c_str(),
                  format_hz(p.frequency_hz).c_str(), "-");
      continue;
    }
    const FeltCheck c = analysis.band().check(p.frequency_hz);
    std::printf("  %6d  %-32s %10s %10s%s\n", p.element->source_line, name_of(p).c_str(),
                format_hz(p.frequency_hz).c_str(), format_db(c.response_db).c_str(), c.weak ? "  weak" : "");
  }
}

}  // namespace vimg::cli
