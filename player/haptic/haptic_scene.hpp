#pragma once
// A volume scene made ready to render: its data, its shaders (built from the scene description)
// and the per-contact shader state of the one probe. Immutable shaders, one mutable feedback
// state; the haptic loop is the only one that evaluates it once it is handed over.
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "primitives/kinaesthetic/combined_feedback.hpp"
#include "primitives/volume/volume_scene.hpp"
#include "storage/volume/volume_scene_io.hpp"

namespace vimg {

class HapticScene {
 public:
  HapticScene(DeviceProfile device, std::vector<std::shared_ptr<const void>> keep_alive,
              std::vector<std::shared_ptr<const ForceShader>> kinaesthetic,
              std::vector<std::shared_ptr<const ForceShader>> vibrotactile);

  const DeviceProfile& device() const { return device_; }
  // Starts a fresh contact (proxies on the probe, phases at zero, no cue ringing).
  void begin_contact() { feedback_.begin_contact(); }
  FeedbackParts evaluate(const InteractionState& interaction) { return feedback_.evaluate(interaction); }

 private:
  DeviceProfile device_;
  std::vector<std::shared_ptr<const void>> keep_alive_;  // data the shaders refer to
  std::vector<std::shared_ptr<const ForceShader>> kinaesthetic_;
  std::vector<std::shared_ptr<const ForceShader>> vibrotactile_;
  CombinedFeedback feedback_;
};

// Builds the shaders a scene describes over its loaded data (mm in the file, SI inside).
std::unique_ptr<HapticScene> build_haptic_scene(const LoadedVolumeScene& loaded);

}  // namespace vimg
