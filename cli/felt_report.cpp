#include "cli/felt_report.hpp"

#include <cstdio>

#include "primitives/actuator/primitive_frequencies.hpp"

namespace vimg::cli {

std::unique_ptr<FeltAnalysis> load_felt_analysis(const std::string& profile_path) {
  FeltAnalysisLoad loaded = load_felt_analysis_file(profile_path);
  for (const std::string& e : loaded.errors) std::fprintf(stderr, "%s\n", e.c_str());
  return std::move(loaded.analysis);
}

void add_felt_warnings(const Image& image, const FeltAnalysis& analysis, DiagnosticList& out) {
  // The messages are built already: the list keeps or counts each one itself.
  for (const FeltWarning& w : felt_warnings(image, analysis)) out.warning(w.element->source_line, w.message);
}

void print_felt_table(const Image& image, const FeltAnalysis& analysis) {
  std::printf("%-13s %s\n", "actuator:", analysis.describe().c_str());
  std::printf("  %6s  %-32s %10s %10s\n", "line", "primitive", "freq_Hz", "resp_dB");
  const bool erm = analysis.profile().response.model == ResponseModel::erm;
  for (const PrimitiveFrequency& p : primitive_frequencies(image, analysis.profile().resonance_hz)) {
    if (erm && p.kind == "dot") {
      // A DOT on an ERM is the motor's own vibration, not a modulation of it.
      std::printf("  %6d  %-32s %10s %10s  (the motor's own vibration)\n", p.element->source_line,
                  primitive_name(p).c_str(), format_hz(p.frequency_hz).c_str(), "-");
      continue;
    }
    const FeltCheck c = analysis.band().check(p.frequency_hz);
    std::printf("  %6d  %-32s %10s %10s%s\n", p.element->source_line, primitive_name(p).c_str(),
                format_hz(p.frequency_hz).c_str(), format_db(c.response_db).c_str(), c.weak ? "  weak" : "");
  }
}

}  // namespace vimg::cli
