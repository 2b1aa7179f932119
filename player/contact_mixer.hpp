#pragma once
// Contact state and mixing for one scene. A contact is one (touch, primitive) pair with its own
// ShaderState; contacts live in a pool allocated once, so stepping never allocates.
//
// Lifecycle, per output step:
//  1. For every finger in contact, the grid is queried with the box of its step segment
//     (previous -> current position). A primitive whose box meets it gets a contact if it has none
//     for that touch: begin_contact() starts it outside, and the shader finds the entry in the step.
//  2. Every contact is stepped. A contact whose touch has lifted is stepped with the finger moved
//     far away (once), then held there: the shader sees an exit and a LINE keeps ringing.
//  3. A contact is dropped when its shader is no longer active() and its touch's step box no longer
//     meets the primitive's box (so a DOT fires again on each new crossing, never twice on one).
// The drives of all contacts are summed along the actuator axis; the caller limits the sum once.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "player/finger_step.hpp"
#include "primitives/shader_state.hpp"

namespace vimg {

class Scene;

class ContactMixer {
 public:
  explicit ContactMixer(std::size_t max_contacts = 512);

  // Drops every contact and renders `scene` from now on (nullptr: silence). Does not allocate.
  void set_scene(const Scene* scene);
  const Scene* scene() const { return scene_; }

  // Advances every contact to time_s and returns the summed, unlimited drive. `touching` holds the
  // fingers in contact during this step; a touch that is absent has lifted.
  double step(std::span<const FingerStep> touching, double time_s, double dt_s);

  std::size_t active_contacts() const { return count_; }
  std::size_t capacity() const { return pool_.size(); }
  // New contacts refused because the pool was full (they are lost, never blocking).
  std::uint64_t refused_contacts() const { return refused_; }

  // Benchmarks only: find candidates by scanning every primitive instead of the grid.
  void use_linear_scan(bool on) { linear_scan_ = on; }

 private:
  struct Contact {
    int finger = 0;
    std::uint32_t touch_id = 0;
    std::uint32_t primitive = 0;
    bool lifted = false;        // its touch ended; the finger was moved away
    Vec3 last_position_m;
    double last_pressure = 1.0;
    ShaderState state;
  };
  void add_contacts_for(const FingerStep& f);
  bool has_contact(const FingerStep& f, std::uint32_t primitive) const;

  const Scene* scene_ = nullptr;
  std::vector<Contact> pool_;  // [0, count_) live, compacted on drop
  std::size_t count_ = 0;
  std::uint64_t refused_ = 0;
  bool linear_scan_ = false;
};

}  // namespace vimg
