#pragma once
// Combined feedback (volume paper, eq 7): the kinaesthetic force plus the vibrotactile force, a
// plain vector sum of every shader's contribution. The parts are kept apart so that callers can
// record them; clamping to a device limit happens once, on the total, by the caller (ForceSum).
// One CombinedFeedback is one contact (one tool): it owns a ShaderState per shader.
#include <vector>

#include "primitives/shader.hpp"

namespace vimg {

struct FeedbackParts {
  Vec3 kinaesthetic_N;
  Vec3 vibrotactile_N;
  Vec3 total_N() const { return kinaesthetic_N + vibrotactile_N; }
};

class CombinedFeedback {
 public:
  CombinedFeedback() = default;
  // The shaders must outlive this object. Allocates here, never in evaluate().
  CombinedFeedback(std::vector<const ForceShader*> kinaesthetic, std::vector<const ForceShader*> vibrotactile);

  // Starts a new contact for every shader.
  void begin_contact();
  // One step: every shader's force at the interaction state, summed per kind.
  FeedbackParts evaluate(const InteractionState& interaction);

 private:
  std::vector<const ForceShader*> kinaesthetic_;
  std::vector<const ForceShader*> vibrotactile_;
  std::vector<ShaderState> kinaesthetic_states_;
  std::vector<ShaderState> vibrotactile_states_;
};

}  // namespace vimg
