// The safety property end to end: random images and gestures, rendered by the player engine into
// the DRV2605L driver on its emulator, never produce an RTP code above the clamp in force.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "hal/drv2605l_registers.hpp"
#include "player/gesture_synth.hpp"
#include "player/offline_render.hpp"
#include "player/scene.hpp"
#include "tests/hal/drv2605l_test_rig.hpp"

namespace vimg {
namespace {

using namespace drv2605l;

Image random_image(std::mt19937& random) {
  std::uniform_real_distribution<double> position(5.0, 95.0), size(1.0, 30.0), gain(0.2, 1.0);
  std::uniform_real_distribution<double> frequency(120.0, 320.0), damping(0.02, 0.3), period(0.5, 6.0);
  std::uniform_int_distribution<int> count(1, 6), kind(0, 2);
  Image image;
  image.width_mm = image.height_mm = 100.0;
  const int elements = count(random);
  for (int e = 0; e < elements; ++e) {
    Element element;
    element.id = "e" + std::to_string(e);
    switch (kind(random)) {
      case 0:
        element.body = Dot{position(random), position(random), size(random) / 6.0, gain(random)};
        break;
      case 1:
        element.body = Line{position(random), position(random), position(random), position(random),
                            size(random) / 5.0, frequency(random), damping(random), gain(random)};
        break;
      default: {
        Surface surface;
        surface.shape = SurfaceShape::rect;
        surface.x_mm = position(random) - 20.0;
        surface.y_mm = position(random) - 20.0;
        surface.width_mm = size(random) * 2.0;
        surface.height_mm = size(random) * 2.0;
        surface.period_mm = period(random);
        surface.relief_mm = period(random) / 6.0;
        surface.gain = gain(random);
        element.body = surface;
      }
    }
    image.children.push_back(element);
  }
  return image;
}

Gesture random_gesture(std::mt19937& random) {
  std::uniform_real_distribution<double> position(0.0, 100.0), speed(20.0, 400.0);
  Gesture gesture;
  for (int finger = 0; finger < 2; ++finger) {
    PathSpec path;
    path.kind = PathSpec::Kind::line;
    path.x0_mm = position(random);
    path.y0_mm = position(random);
    path.x1_mm = position(random);
    path.y1_mm = position(random);
    SamplingSpec sampling;
    sampling.speed_mm_per_s = speed(random);
    sampling.finger = finger;
    sampling.start_time_s = 0.05 * finger;
    if (check_synthesis(path, sampling)) continue;
    gesture.strokes.push_back(synthesise_stroke(path, sampling));
  }
  return gesture;
}

TEST(Drv2605lRenderProperty, RandomImagesAndGesturesNeverExceedTheClamp) {
  std::mt19937 random(20261122u);
  const auto profile = test::lra_profile();
  const auto full = static_cast<std::uint8_t>(255);
  const auto open_clamp = static_cast<std::uint8_t>(std::floor(255.0 * profile.rated_voltage_V / profile.overdrive_clamp_V));
  int rtp_writes = 0;
  for (int trial = 0; trial < 25; ++trial) {
    const Image image = random_image(random);
    const Gesture gesture = random_gesture(random);
    if (gesture.strokes.empty()) continue;
    test::Drv2605lRig rig(profile);
    SceneOptions options;
    options.carrier_frequency_hz = profile.resonance_hz;
    const auto scene = compile_scene(image, options);
    render_gesture(*scene, gesture, *rig.driver);
    bool open_loop = false;
    for (const auto& access : rig.chip.traffic()) {
      if (!access.write) continue;
      if (access.reg == kControl3) open_loop = (access.value & kControl3LraOpenLoop) != 0;
      if (access.reg == kRtpInput) {
        ++rtp_writes;
        ASSERT_LE(access.value, open_loop ? open_clamp : full) << "trial " << trial << " at " << access.time_us;
      }
    }
    EXPECT_TRUE(rig.chip.standby()) << "trial " << trial;  // render_gesture closes the sink
    EXPECT_TRUE(rig.chip.violations().empty()) << "trial " << trial;
  }
  EXPECT_GT(rtp_writes, 100);  // the trials did drive the actuator
}

}  // namespace
}  // namespace vimg
