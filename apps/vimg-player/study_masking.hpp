#pragma once
// The masking noise of a matching test (the study file's <maskingNoise device="..." level="..."/>):
// white noise (study_noise.hpp) on a named SDL audio output that is not the actuator's, from the
// first screen to the last, so that the participant cannot hear the actuator.
// Threads: open() and the destructor on the UI thread; the noise is made in SDL's audio callback.
#include <SDL.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "apps/vimg-player/study_noise.hpp"
#include "hal/output_spec.hpp"
#include "storage/study/study_file.hpp"

namespace vimg::player_app {

class MaskingNoisePlayer {
 public:
  MaskingNoisePlayer() = default;
  ~MaskingNoisePlayer();
  MaskingNoisePlayer(const MaskingNoisePlayer&) = delete;
  MaskingNoisePlayer& operator=(const MaskingNoisePlayer&) = delete;

  // Starts the noise. Returns the error, naming the devices there are, when the device does not
  // exist, is the actuator's own (`actuator`: an audio output by that name, or the default output
  // when SDL can name it), or cannot be opened.
  std::optional<std::string> start(const MaskingNoise& noise, const OutputSpec& actuator);
  std::string description() const { return description_; }

 private:
  static void callback(void* self, Uint8* stream, int length);

  std::unique_ptr<WhiteNoise> noise_;
  SDL_AudioDeviceID device_ = 0;
  bool subsystem_ = false;
  std::string description_;
};

}  // namespace vimg::player_app
