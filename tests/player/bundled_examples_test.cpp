// The bundled example and gestures (assets/) rendered as `vimg render` does, checked against spec 5.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "render_support.hpp"
#include "storage/gesture_csv.hpp"
#include "storage/image_io.hpp"

namespace vimg {
namespace {

using test::Rendered;

const std::string kAssets = std::string(VIMG_SOURCE_DIR) + "/assets/";

Image smiley() {
  const auto r = load_image_file(kAssets + "examples/smiley.vimg");
  EXPECT_TRUE(r.ok());
  return r.image.value_or(Image{});
}

Gesture gesture(const std::string& name) {
  const auto r = load_gesture_file(kAssets + "gestures/" + name);
  EXPECT_TRUE(r.ok()) << (r.errors.empty() ? "" : r.errors.front());
  return r.gesture.value_or(Gesture{});
}

Image without(Image img, const std::string& id) {
  std::erase_if(img.children, [&](const Element& e) { return e.id == id; });
  return img;
}

void expect_bounded_and_silent_at_end(const Rendered& r) {
  ASSERT_FALSE(r.d.empty());
  for (float v : r.d) ASSERT_LE(std::fabs(v), 1.0f);
  EXPECT_EQ(r.d.back(), 0.0f);
}

TEST(BundledExamples, EveryGestureRendersBoundedAndEndsSilent) {
  for (const char* g : {"smiley_eyes.csv", "smiley_mouth.csv", "smiley_two_fingers.csv", "smiley_circle_60hz.csv",
                        "smiley_circle_240hz.csv"}) {
    SCOPED_TRACE(g);
    expect_bounded_and_silent_at_end(test::render(smiley(), gesture(g)));
  }
}

TEST(BundledExamples, EyesFireExactlyWhileTheFingerIsOnThem) {
  // The eyes gesture runs along y = 55 from x = 10 at 100 mm/s; the eyes (radius 1.5) are at x = 25
  // and x = 45. Rendering with and without the eyes differs only while the finger is on an eye.
  const auto with = test::render(smiley(), gesture("smiley_eyes.csv"));
  const auto bare = test::render(without(smiley(), "eyes"), gesture("smiley_eyes.csv"));
  ASSERT_EQ(with.d.size(), bare.d.size());
  const double windows[2][2] = {{0.135, 0.165}, {0.335, 0.365}};
  const double slack = 1.0 / 8000.0 + 1e-9;
  for (std::size_t i = 0; i < with.d.size(); ++i) {
    const double t = with.time_of(i);
    const bool on_eye = (t >= windows[0][0] - slack && t <= windows[0][1] + slack) ||
                        (t >= windows[1][0] - slack && t <= windows[1][1] + slack);
    if (!on_eye) {
      ASSERT_EQ(with.d[i], bare.d[i]) << "t = " << t;
    }
  }
  for (const auto& w : windows) {
    double diff = 0.0;
    for (std::size_t i = with.index_at(w[0]); i < with.index_at(w[1]); ++i)
      diff = std::max(diff, static_cast<double>(std::fabs(with.d[i] - bare.d[i])));
    EXPECT_GT(diff, 0.2);
  }
}

TEST(BundledExamples, MouthRingsOnAfterTheFingerLifts) {
  // Down at y = 80 (t = 0.05), through the band y 89..91 (exit at t = 0.16), lift at y = 95 (t = 0.2).
  const auto r = test::render(smiley(), gesture("smiley_mouth.csv"));
  const double expected_f = 175.0 * std::sqrt(1.0 - 0.05 * 0.05);
  const double decay = 2.0 * std::numbers::pi * 175.0 * 0.05;
  EXPECT_NEAR(r.zero_crossing_frequency_hz(0.201, 0.24), expected_f, 0.02 * expected_f);
  EXPECT_NEAR(r.envelope_decay_per_s(0.201, 0.25, 0.8 * 0.02, 0.49), decay, 0.1 * decay);
  const auto span = r.nonzero_span(0.201, 10.0);
  ASSERT_TRUE(span.has_value());
  EXPECT_NEAR(span->second - 0.16, std::log(100.0) / decay, 0.1 * std::log(100.0) / decay);
}

TEST(BundledExamples, CircleThroughTheEyesHasTheSameTimingAt60And240Hz) {
  const Image bare = without(smiley(), "eyes");
  auto eye_pulses = [&](const char* g) {
    const auto with = test::render(smiley(), gesture(g));
    const auto none = test::render(bare, gesture(g));
    std::vector<double> starts;
    bool in = false;
    for (std::size_t i = 0; i < std::min(with.d.size(), none.d.size()); ++i) {
      const bool differs = with.d[i] != none.d[i];
      if (differs && !in) starts.push_back(with.time_of(i));
      in = differs;
    }
    return starts;
  };
  const auto a = eye_pulses("smiley_circle_60hz.csv");
  const auto b = eye_pulses("smiley_circle_240hz.csv");
  ASSERT_EQ(b.size(), 2u);
  ASSERT_EQ(a.size(), b.size());
  const double turn_s = 2.0 * std::numbers::pi * 18.0 / 80.0;
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_NEAR(a[i], b[i], 0.02 * 0.0375 + 0.002) << i;
  EXPECT_LT(b.back(), turn_s);
}

}  // namespace
}  // namespace vimg
