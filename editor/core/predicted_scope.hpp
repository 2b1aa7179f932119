#pragma once
// The oscilloscope's data while playing: the drive the DriveTap saw and the acceleration the
// chosen actuator is predicted to give from it (the ActuatorModel of its profile, docs/actuators.md),
// sample for sample. The model runs here, on the GUI thread, over the samples tapped since the last
// frame; the render thread only writes the drive into the tap's ring, as before. When the GUI falls
// more than DriveTap::kRingSize / 2 samples behind, the samples in between are not modelled: the
// model goes on from the oldest sample still offered (its state is that of a short gap).
// The acceleration is normalized as the model's (0 dB at its peak): the ideal profile gives the
// drive itself.
// Threads: GUI thread only (it reads the tap with DriveTap::copy_since).
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "editor/core/drive_tap.hpp"
#include "primitives/actuator/actuator_model.hpp"

namespace vimg::editor {

class PredictedScope {
 public:
  static constexpr std::size_t kHistory = DriveTap::kRingSize;

  // The actuator's response; `generation` changes when the profile does (the model starts anew).
  void set_response(const ResponseParams& params, std::uint64_t generation);
  // Models the samples written to `tap` since the last call. A different tap (a new play
  // session) or a new sample rate starts anew.
  void update(const DriveTap& tap);

  // The last `count` samples of drive and of predicted acceleration, oldest first, zero-padded at
  // the start while fewer have been seen.
  void recent(std::size_t count, std::vector<float>& drive, std::vector<float>& acceleration) const;
  // Samples modelled since the start, and samples left out because the GUI fell behind.
  std::uint64_t modelled() const { return modelled_; }
  std::uint64_t skipped() const { return skipped_; }

 private:
  void restart();

  ResponseParams params_;
  std::uint64_t generation_ = 0;
  const DriveTap* tap_ = nullptr;
  double sample_rate_hz_ = 0.0;
  std::optional<ActuatorModel> model_;
  std::uint64_t cursor_ = 0;
  std::uint64_t modelled_ = 0;
  std::uint64_t skipped_ = 0;
  std::vector<float> fresh_;
  std::vector<float> drive_ = std::vector<float>(kHistory, 0.0f);
  std::vector<float> acceleration_ = std::vector<float>(kHistory, 0.0f);
  std::size_t head_ = 0;  // where the next sample goes in the two histories
};

}  // namespace vimg::editor
