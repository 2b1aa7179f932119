#pragma once
// The predicted feel of an image on an actuator, as `vimg validate --actuator` and `vimg info
// --actuator` report it (docs/actuators.md, "Felt band"). The model is designed at
// kFeltAnalysisRateHz, the highest rate `vimg render` writes.
#include <memory>
#include <optional>
#include <string>

#include "hal/actuator_profile.hpp"
#include "primitives/actuator/actuator_model.hpp"
#include "primitives/actuator/felt_band.hpp"
#include "primitives/image.hpp"
#include "storage/diagnostic.hpp"

namespace vimg::cli {

inline constexpr double kFeltAnalysisRateHz = 48000.0;

// A profile with its model and felt band. Not copyable: the band refers to the model.
class FeltAnalysis {
 public:
  explicit FeltAnalysis(ActuatorProfile profile)
      : profile_(std::move(profile)), model_(profile_.response, kFeltAnalysisRateHz), band_(model_) {}
  FeltAnalysis(const FeltAnalysis&) = delete;
  FeltAnalysis& operator=(const FeltAnalysis&) = delete;

  const ActuatorProfile& profile() const { return profile_; }
  const FeltBand& band() const { return band_; }
  // "lra-175hz-drv2605l (lra, felt band 151-203 Hz: within 10 dB of the peak at 175 Hz)"
  std::string describe() const;

 private:
  ActuatorProfile profile_;
  ActuatorModel model_;
  FeltBand band_;
};

// Loads the profile; prints its errors to stderr and returns null when it has any.
std::unique_ptr<FeltAnalysis> load_felt_analysis(const std::string& profile_path);

// A frequency as people read it: "175", "16.3", "0.5".
std::string format_hz(double frequency_hz);

// One warning per SURFACE and LINE whose frequency at fullSpeed is weak on the actuator, at the
// element's line.
void add_felt_warnings(const Image& image, const FeltAnalysis& analysis, DiagnosticList& out);

// `vimg info --actuator`: one row per primitive with its frequency at fullSpeed and its response.
void print_felt_table(const Image& image, const FeltAnalysis& analysis);

}  // namespace vimg::cli
