#pragma once
// The shader API shared by the touch player and the kinaesthetic volume backend.
//
// A shader is an immutable description (geometry, parameters, data). Everything that changes
// while a contact lasts lives in a ShaderState that the caller owns and passes in, so one shader
// serves any number of fingers or tools at once and the caller decides when contacts begin and end.
#include "primitives/interaction_state.hpp"
#include "primitives/shader_state.hpp"
#include "primitives/vec3.hpp"

namespace vimg {

class ForceShader {
 public:
  virtual ~ForceShader() = default;

  // Initializes the state of a new contact. The next call to force_N for that contact sees
  // InteractionState::previous_position_m as where the contact came from.
  virtual void begin_contact(ShaderState& state) const = 0;

  // The force contribution in newtons at state.time_s. Advances the contact state by one step.
  virtual Vec3 force_N(const InteractionState& interaction, ShaderState& state) const = 0;

  // True while the contact still produces output or may produce it on the next step (in
  // contact, or ringing down after release). A caller may drop an inactive contact.
  virtual bool active(const ShaderState& state) const = 0;
};

}  // namespace vimg
