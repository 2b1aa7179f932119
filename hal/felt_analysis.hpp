#pragma once
// The predicted feel of an image on an actuator profile (docs/actuators.md, "Felt band"): the one
// place that decides which primitives are weak and words the warning. `vimg validate --actuator`
// prints these warnings at the element's line, `vimg info --actuator` lists the same checks, and
// the editor marks the same primitives on its canvas with the same words in its inspector.
// The model is designed at kFeltAnalysisRateHz, the highest rate `vimg render` writes, whatever
// rate the image is later played at, so that every tool gives the same answer.
//
// Threads: construction designs the model and scans the band (not real-time); the rest are pure
// functions of their inputs.
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "storage/actuator_profile.hpp"
#include "primitives/actuator/actuator_model.hpp"
#include "primitives/actuator/felt_band.hpp"
#include "primitives/actuator/primitive_frequencies.hpp"
#include "primitives/image.hpp"

namespace vimg {

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

struct FeltAnalysisLoad {
  std::unique_ptr<FeltAnalysis> analysis;  // null when the profile has errors
  std::vector<std::string> errors;         // "FILE:LINE: error: problem"
};
FeltAnalysisLoad load_felt_analysis_file(const std::filesystem::path& profile_path);

// One weak SURFACE or LINE: its frequency at fullSpeed is more than kFeltWithinDb below the
// actuator's peak. A DOT plays at the actuator's own carrier and is never weak.
struct FeltWarning {
  const Element* element = nullptr;  // points into the image
  FeltCheck check;
  // "surface 'sand' at 20 Hz (fullSpeed 100 mm/s / period 5 mm) is -25.1 dB on actuator
  // 'lra-175hz-drv2605l', outside its felt band 151-203 Hz (within 10 dB of the peak); a period of
  // 0.6 mm (163 Hz) would be felt"
  std::string message;
};
std::vector<FeltWarning> felt_warnings(const Image& image, const FeltAnalysis& analysis);
// The same primitives as their indices in primitive_frequencies' paint order (`vimg separate`
// keeps every primitive felt that was felt: study/separate.hpp).
std::vector<std::size_t> weak_primitive_indices(const Image& image, const FeltAnalysis& analysis);

// A frequency as people read it: "175", "16.3", "0.5".
std::string format_hz(double frequency_hz);
// A response in dB with one decimal, never "-0.0", at least -999.
std::string format_db(double db);
// "surface 'sand'" (the kind, and the id when there is one, escaped).
std::string primitive_name(const PrimitiveFrequency& p);

}  // namespace vimg
