#include "hal/felt_analysis.hpp"

#include <cstdio>

#include "storage/diagnostic.hpp"

namespace vimg {

namespace {

std::string format_mm(double mm) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", mm);
  return text;
}

std::string band_text(const FrequencyBand& band) {
  return format_hz(band.low_hz) + "-" + format_hz(band.high_hz) + " Hz";
}

std::string warning_text(const PrimitiveFrequency& p, const FeltCheck& c, const FeltAnalysis& analysis,
                         double full_speed_mm_per_s) {
  std::string message = primitive_name(p) + " at " + format_hz(p.frequency_hz) + " Hz";
  std::string suggestion;
  if (const auto* surface = std::get_if<Surface>(&p.element->body)) {
    message += " (fullSpeed " + format_hz(full_speed_mm_per_s) + " mm/s / period " + format_mm(surface->period_mm) +
               " mm)";
    suggestion = "a period of " + format_mm(full_speed_mm_per_s / c.suggested_frequency_hz) + " mm (" +
                 format_hz(c.suggested_frequency_hz) + " Hz) would be felt";
  } else {
    suggestion = "a frequency of " + format_hz(c.suggested_frequency_hz) + " Hz would be felt";
  }
  return message + " is " + format_db(c.response_db) + " dB on actuator '" + escape_input(analysis.profile().name) +
         "', outside its felt band " + band_text(analysis.band().felt()) + " (within " + format_hz(kFeltWithinDb) +
         " dB of the peak); " + suggestion;
}

}  // namespace

std::string format_hz(double frequency_hz) {
  char text[32];
  std::snprintf(text, sizeof text, frequency_hz >= 100.0 ? "%.0f" : "%.3g", frequency_hz);
  return text;
}

std::string format_db(double db) {
  char text[32];
  // No "-0.0": a response within 0.05 dB of the peak is shown as 0.0.
  std::snprintf(text, sizeof text, "%.1f", db < -999.0 ? -999.0 : (db > -0.05 ? 0.0 : db));
  return text;
}

std::string primitive_name(const PrimitiveFrequency& p) {
  return std::string(p.kind) + (p.element->id.empty() ? "" : " '" + escape_input(p.element->id) + "'");
}

std::string FeltAnalysis::describe() const {
  const std::string peak = band_.peak_hz() > 0.0 ? " at " + format_hz(band_.peak_hz()) + " Hz" : " at 0 Hz";
  return escape_input(profile_.name) + " (" + std::string(to_string(profile_.response.model)) + ", felt band " +
         band_text(band_.felt()) + ": within " + format_hz(kFeltWithinDb) + " dB of the peak" + peak + ")";
}

FeltAnalysisLoad load_felt_analysis_file(const std::filesystem::path& profile_path) {
  ProfileLoadResult loaded = load_actuator_profile(profile_path);
  FeltAnalysisLoad out;
  out.errors = std::move(loaded.errors);
  if (loaded.profile && out.errors.empty()) out.analysis = std::make_unique<FeltAnalysis>(std::move(*loaded.profile));
  return out;
}

std::vector<FeltWarning> felt_warnings(const Image& image, const FeltAnalysis& analysis) {
  std::vector<FeltWarning> out;
  const double full_speed = image.effective_interaction().full_speed_mm_per_s;
  for (const PrimitiveFrequency& p : primitive_frequencies(image, analysis.profile().resonance_hz)) {
    if (p.kind == "dot") continue;  // a DOT plays at the actuator's own carrier
    const FeltCheck c = analysis.band().check(p.frequency_hz);
    if (!c.weak) continue;
    out.push_back({p.element, c, warning_text(p, c, analysis, full_speed)});
  }
  return out;
}

std::vector<std::size_t> weak_primitive_indices(const Image& image, const FeltAnalysis& analysis) {
  std::vector<std::size_t> out;
  const std::vector<PrimitiveFrequency> all = primitive_frequencies(image, analysis.profile().resonance_hz);
  const std::vector<FeltWarning> weak = felt_warnings(image, analysis);
  for (std::size_t k = 0; k < all.size(); ++k)
    for (const FeltWarning& w : weak)
      if (w.element == all[k].element) out.push_back(k);
  return out;
}

}  // namespace vimg
