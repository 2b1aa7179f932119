#include "player/contact_mixer.hpp"

#include "player/scene.hpp"

namespace vimg {

namespace {

// Where a lifted finger is moved so that its contacts see it leave: far off any canvas (1 km).
constexpr double kFarAway_m = 1000.0;

}  // namespace

ContactMixer::ContactMixer(std::size_t max_contacts) : pool_(max_contacts) {}

void ContactMixer::set_scene(const Scene* scene) {
  scene_ = scene;
  count_ = 0;
}

bool ContactMixer::has_contact(const FingerStep& f, std::uint32_t primitive) const {
  for (std::size_t i = 0; i < count_; ++i) {
    const Contact& c = pool_[i];
    if (c.primitive == primitive && c.touch_id == f.touch_id && c.finger == f.finger && !c.lifted) return true;
  }
  return false;
}

void ContactMixer::add_contacts_for(const FingerStep& f) {
  const Bounds2M query = Bounds2M::of_segment(f.previous_position_m, f.position_m);
  auto consider = [&](std::uint32_t p) {
    if (!scene_->bounds(p).intersects(query) || has_contact(f, p)) return;
    if (count_ == pool_.size()) {
      ++refused_;
      return;
    }
    Contact& c = pool_[count_++];
    c.finger = f.finger;
    c.touch_id = f.touch_id;
    c.primitive = p;
    c.lifted = false;
    c.last_position_m = f.previous_position_m;
    c.last_pressure = f.pressure;
    scene_->shader(p).begin_contact(c.state);
  };
  if (linear_scan_) {
    const auto n = static_cast<std::uint32_t>(scene_->size());
    for (std::uint32_t p = 0; p < n; ++p) consider(p);
  } else {
    scene_->for_each_candidate(query, consider);
  }
}

double ContactMixer::step(std::span<const FingerStep> touching, double time_s, double dt_s) {
  if (scene_ == nullptr) return 0.0;
  for (const FingerStep& f : touching) add_contacts_for(f);

  double sum = 0.0;
  std::size_t i = 0;
  while (i < count_) {
    Contact& c = pool_[i];
    const FingerStep* finger = nullptr;
    if (!c.lifted) {
      for (const FingerStep& f : touching) {
        if (f.finger == c.finger && f.touch_id == c.touch_id) {
          finger = &f;
          break;
        }
      }
    }
    InteractionState s;
    s.time_s = time_s;
    s.dt_s = dt_s;
    s.tool_id = c.finger;
    bool near = false;
    if (finger != nullptr) {
      s.previous_position_m = finger->previous_position_m;
      s.position_m = finger->position_m;
      s.velocity_m_per_s = finger->velocity_m_per_s;
      s.pressure = finger->pressure;
      near = Bounds2M::of_segment(s.previous_position_m, s.position_m).intersects(scene_->bounds(c.primitive));
    } else {
      // The touch has ended: the finger is gone from the start of this step and stays away. The
      // whole step lies far off the canvas, so it crosses no primitive on its way out (a path from
      // the last position could cross a ringing LINE and pluck it again with zero speed).
      const Vec3 away = c.last_position_m + Vec3{kFarAway_m, kFarAway_m, 0.0};
      s.previous_position_m = away;
      s.position_m = away;
      s.pressure = c.last_pressure;
      c.lifted = true;
    }
    const Scene& scene = *scene_;
    sum += scene.drive_of(scene.shader(c.primitive).force_N(s, c.state));
    if (finger != nullptr) {
      c.last_position_m = s.position_m;
      c.last_pressure = s.pressure;
    }
    if (!near && !scene.shader(c.primitive).active(c.state)) {
      pool_[i] = pool_[count_ - 1];  // drop: move the last contact here
      --count_;
      continue;
    }
    ++i;
  }
  return sum;
}

}  // namespace vimg
