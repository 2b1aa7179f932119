// Spec section 5: properties of rendered drive, checked on offline renders with the spec's tolerances.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "render_support.hpp"

namespace vimg {
namespace {

using namespace vimg::test;

constexpr double kRate = 8000.0;
constexpr double kSample = 1.0 / kRate;

// ---- 5.1 bounds and 5.2 silence ----

TEST(RenderSpec, BoundsHoldWithTenFingersOverOverlappingPrimitives) {
  std::vector<Element> els;
  for (int i = 0; i < 4; ++i) els.push_back(element("s" + std::to_string(i), rect_surface(0, 0, 100, 100, 2.0 + i, 0.5, 1.0)));
  for (int i = 0; i < 6; ++i) els.push_back(element("l" + std::to_string(i), line(0, 40 + i * 0.2, 100, 40 + i * 0.2, 3, 175, 0.05, 1.0)));
  Group g;
  for (int i = 0; i < 5; ++i) g.children.push_back(element("d" + std::to_string(i), dot(50, 40, 3, 1.0)));
  els.push_back(element("g", g));
  std::vector<GestureStroke> strokes;
  for (int f = 0; f < 10; ++f) strokes.push_back(line_stroke(48 + 0.3 * f, 20, 48 + 0.3 * f, 60, 100.0 + 20 * f, 120, 0.01 * f, f));
  const auto r = render(image_of(els), gesture_of(strokes));
  double peak = 0.0;
  for (float v : r.d) {
    ASSERT_LE(std::fabs(v), 1.0f);
    peak = std::max(peak, static_cast<double>(std::fabs(v)));
  }
  EXPECT_GT(peak, 0.9);  // the sum really exceeded the limiter's knee
}

TEST(RenderSpec, SilenceBeforeContactAndAfterEveryRingDown) {
  const auto img = image_of({element("d", dot(50, 50, 2)), element("l", line(20, 70, 80, 70, 2, 175, 0.05, 0.5)),
                             element("s", rect_surface(0, 80, 100, 20, 2, 0.5, 0.5))});
  const auto r = render(img, gesture_of({line_stroke(50, 30, 50, 95, 100, 120, 0.2)}));
  const auto before = r.nonzero_span(0.0, 0.2);
  EXPECT_FALSE(before.has_value());
  // The gesture ends at 0.85 s; the line's ring ended long before; the render stops once silent
  // and the last samples are exactly zero.
  ASSERT_GT(r.d.size(), 10u);
  EXPECT_EQ(r.d.back(), 0.0f);
  const auto end = r.nonzero_span(0.86, 100.0);
  EXPECT_FALSE(end.has_value());
}

// ---- 5.3 DOT timing and carrier ----

TEST(RenderSpec, DotDrivesOnlyWhileTheFingerIsWithinItsRadiusAtTheCarrier) {
  for (const double speed : {20.0, 40.0, 100.0, 250.0}) {
    SCOPED_TRACE(speed);
    const auto img = image_of({element("d", dot(50, 50, 2))});
    const double t0 = 0.1;
    const auto r = render(img, gesture_of({line_stroke(30, 50, 70, 50, speed, 120, t0)}));
    const double alpha = t0 + 18.0 / speed, beta = t0 + 22.0 / speed;
    const auto span = r.nonzero_span(0.0, 100.0);
    ASSERT_TRUE(span.has_value());
    EXPECT_GE(span->first, alpha - 1e-9);
    EXPECT_LE(span->first, alpha + kSample + 1e-9);
    EXPECT_LE(span->second, beta + 1e-9);
    EXPECT_GE(span->second, beta - kSample - 1e-9);
    if (beta - alpha >= 0.05) {
      EXPECT_NEAR(r.zero_crossing_frequency_hz(alpha, beta), 175.0, 175.0 * 0.02);
    }
  }
}

TEST(RenderSpec, DotFiresAgainOnEachNewCrossing) {
  const auto img = image_of({element("d", dot(50, 50, 2))});
  GestureStroke s = line_stroke(40, 50, 60, 50, 100, 120, 0.0);
  GestureStroke back = line_stroke(60, 50, 40, 50, 100, 120, s.points.back().time_s);
  s.points.insert(s.points.end(), back.points.begin() + 1, back.points.end());
  const auto r = render(img, gesture_of({s}));
  // Crossings at 0.08..0.12 s and 0.28..0.32 s.
  EXPECT_GT(r.peak(0.08, 0.12), 0.5);
  EXPECT_FALSE(r.nonzero_span(0.125, 0.275).has_value());
  EXPECT_GT(r.peak(0.28, 0.32), 0.5);
}

// ---- 5.4 DOT strength ----

TEST(RenderSpec, DotPeakDoesNotDecreaseWithEntrySpeedUpToFullSpeed) {
  const auto img = image_of({element("d", dot(50, 50, 3))}, 100.0);
  double previous = 0.0;
  for (const double speed : {5.0, 10.0, 20.0, 35.0, 50.0, 75.0, 100.0}) {
    const auto r = render(img, gesture_of({line_stroke(30, 50, 70, 50, speed, 120, 0.0)}));
    const double p = r.peak(0.0, 100.0);
    EXPECT_GE(p, previous - 1e-6) << speed;
    previous = p;
  }
  EXPECT_GT(previous, 0.6);
}

// ---- 5.5 LINE ring-down ----

struct RingCase {
  double frequency_hz, damping, gain;
};

void expect_ring_down(const Rendered& r, double release_s, const RingCase& c, double amplitude_limit) {
  const double omega_n = 2.0 * std::numbers::pi * c.frequency_hz;
  const double expected_f = c.frequency_hz * std::sqrt(1.0 - c.damping * c.damping);
  const double decay = omega_n * c.damping;
  const double ring_s = std::log(100.0) / decay;
  // Frequency over the first half of the ring.
  EXPECT_NEAR(r.zero_crossing_frequency_hz(release_s + 0.002, release_s + 0.5 * ring_s), expected_f, expected_f * 0.02);
  // Envelope decay over the peaks below the limiter's knee and above the last 2 % of the start.
  const double measured = r.envelope_decay_per_s(release_s, release_s + ring_s, 0.02 * amplitude_limit, 0.49);
  EXPECT_NEAR(measured, decay, decay * 0.10);
  // It stops, exactly, when the envelope is at -40 dB of its start.
  const auto span = r.nonzero_span(release_s, 1e9);
  ASSERT_TRUE(span.has_value());
  EXPECT_NEAR(span->second - release_s, ring_s, ring_s * 0.10);
  EXPECT_EQ(r.d.back(), 0.0f);
  // Over the last half period the envelope is 0.01 * A0 * exp(decay * half period) at most.
  const double half_period = 0.5 / expected_f;
  const double tail = r.peak(span->second - half_period, span->second + kSample);
  EXPECT_LT(tail, 0.01 * amplitude_limit * std::exp(decay * half_period) * 1.1);
}

TEST(RenderSpec, LineRingsAtTheDampedFrequencyAndDecaysAfterTheFingerLeaves) {
  for (const RingCase c : {RingCase{175, 0.05, 0.4}, RingCase{120, 0.03, 0.3}, RingCase{250, 0.1, 0.45}}) {
    SCOPED_TRACE(c.frequency_hz);
    const auto img = image_of({element("l", line(20, 50, 80, 50, 2, c.frequency_hz, c.damping, c.gain))});
    const double t0 = 0.05;
    // Vertical crossing at 100 mm/s: the band is y in [49, 51]; the finger leaves at y = 51.
    const auto r = render(img, gesture_of({line_stroke(50, 40, 50, 60, 100, 120, t0)}));
    const double beta = t0 + 0.11;
    expect_ring_down(r, beta, c, c.gain);
  }
}

TEST(RenderSpec, LineKeepsRingingAfterTheFingerLiftsInsideItsBand) {
  const RingCase c{175, 0.05, 0.4};
  const auto img = image_of({element("l", line(20, 50, 80, 50, 2, c.frequency_hz, c.damping, c.gain))});
  const auto r = render(img, gesture_of({line_stroke(50, 45, 50, 50, 100, 120, 0.0)}));  // lifts at 0.05 s in the band
  expect_ring_down(r, 0.05, c, c.gain);
}

TEST(RenderSpec, LiftingElsewhereDoesNotCutARingDownShort) {
  // The finger crosses the band upwards (leaving it at y = 49 at 0.11 s) and lifts at (30, 45) at
  // 0.15 s, while the line still rings. Wherever the lifted finger is taken, it must not pluck again.
  const RingCase c{175, 0.05, 0.4};
  const auto img = image_of({element("l", line(20, 50, 80, 50, 2, c.frequency_hz, c.damping, c.gain))});
  const auto r = render(img, gesture_of({line_stroke(30, 60, 30, 45, 100, 120, 0.0)}));
  expect_ring_down(r, 0.11, c, c.gain);
}

// ---- 5.6 SURFACE frequency ----

TEST(RenderSpec, SurfaceFrequencyFollowsSpeedOverPeriod) {
  for (const SurfacePattern pattern : {SurfacePattern::sine, SurfacePattern::square, SurfacePattern::triangle}) {
    for (const double period : {1.0, 2.0, 5.0}) {
      for (const double speed : {25.0, 60.0, 100.0, 200.0, 450.0}) {
        const double f = speed / period;
        if (f < 20.0 || f > 500.0) continue;
        SCOPED_TRACE(testing::Message() << "pattern " << static_cast<int>(pattern) << " period " << period
                                        << " speed " << speed);
        const auto img = image_of({element("s", rect_surface(0, 0, 100, 100, period, 0.5, 0.4, pattern))});
        const auto r = render(img, gesture_of({line_stroke(10, 50, 90, 50, speed, 120, 0.0)}));
        const double dur = 80.0 / speed;
        EXPECT_NEAR(r.zero_crossing_frequency_hz(0.1 * dur, 0.9 * dur), f, f * 0.03);
      }
    }
  }
}

// ---- 5.7 SURFACE at rest ----

TEST(RenderSpec, SurfaceFallsSilentWithin50msOfTheFingerStopping) {
  const auto img = image_of({element("s", rect_surface(0, 0, 100, 100, 2, 0.5, 1.0))});
  const auto r = render(img, gesture_of({line_stroke(10, 50, 50, 50, 100, 120, 0.0, 0, 0.3)}));
  EXPECT_GT(r.peak(0.1, 0.35), 0.5);
  EXPECT_LT(r.peak(0.4 + 0.05, 0.7), 0.01);
}

// ---- 5.8 gesture sampling ----

struct Measured {
  double dot_in_s, dot_out_s, line_f_hz, line_end_s, surface_f_hz;
};

Measured measure_circle(double event_rate_hz) {
  // A circle of radius 20 mm around (50,50) at 100 mm/s, starting at angle 0 (70,50) and turning
  // towards +y. It meets the dot at (50,70), the line across (30,50), and the surface x 60..80, y 25..45.
  const auto img = image_of({element("d", dot(50, 70, 1.5)), element("l", line(25, 50, 35, 50, 2, 175, 0.05, 0.4)),
                             element("s", rect_surface(60, 25, 20, 20, 1.0, 0.5, 0.4))});
  PathSpec p;
  p.kind = PathSpec::Kind::circle;
  p.cx_mm = 50; p.cy_mm = 50; p.radius_mm = 20;
  SamplingSpec s;
  s.speed_mm_per_s = 100;
  s.event_rate_hz = event_rate_hz;
  const auto r = render(img, gesture_of({synthesise_stroke(p, s)}));
  const double quarter = 2 * std::numbers::pi * 20 / 4 / 100;  // seconds per quarter turn
  Measured m{};
  const auto dot_span = r.nonzero_span(0.8 * quarter, 1.2 * quarter);
  if (dot_span) {
    m.dot_in_s = dot_span->first;
    m.dot_out_s = dot_span->second;
  }
  m.line_f_hz = r.zero_crossing_frequency_hz(2 * quarter + 0.02, 2 * quarter + 0.06);
  const auto line_span = r.nonzero_span(2 * quarter - 0.02, 3 * quarter);
  if (line_span) m.line_end_s = line_span->second;
  m.surface_f_hz = r.zero_crossing_frequency_hz(3.6 * quarter, 3.85 * quarter);
  return m;
}

TEST(RenderSpec, SixtyAndTwoHundredFortyHertzGesturesGiveTheSameTimingsAndFrequencies) {
  const Measured a = measure_circle(60.0), b = measure_circle(240.0);
  const double pulse = b.dot_out_s - b.dot_in_s;
  ASSERT_GT(pulse, 0.02);
  EXPECT_NEAR(a.dot_in_s, b.dot_in_s, 0.02 * pulse + kSample);
  EXPECT_NEAR(a.dot_out_s, b.dot_out_s, 0.02 * pulse + kSample);
  EXPECT_NEAR(a.line_f_hz, b.line_f_hz, 0.02 * b.line_f_hz);
  EXPECT_NEAR(a.line_f_hz, 175.0 * std::sqrt(1 - 0.0025), 0.02 * 175.0);
  EXPECT_NEAR(a.line_end_s, b.line_end_s, 0.02 * 0.084);
  EXPECT_NEAR(a.surface_f_hz, b.surface_f_hz, 0.02 * b.surface_f_hz);
  EXPECT_NEAR(b.surface_f_hz, 100.0, 3.0);
}

TEST(RenderSpec, JitteredEventTimingKeepsTimingsAndFrequencies) {
  const auto img = image_of({element("d", dot(50, 50, 2)), element("s", rect_surface(60, 0, 40, 100, 2, 0.5, 0.4))});
  auto make = [&](double jitter_s, std::uint32_t seed) {
    PathSpec p;
    p.x0_mm = 30; p.y0_mm = 50; p.x1_mm = 95; p.y1_mm = 50;
    SamplingSpec s;
    s.speed_mm_per_s = 100;
    s.event_rate_hz = 90;
    s.time_jitter_s = jitter_s;
    s.seed = seed;
    return render(img, gesture_of({synthesise_stroke(p, s)}));
  };
  const auto exact = make(0.0, 1);
  const auto jittered = make(0.008, 42);
  const auto a = exact.nonzero_span(0.0, 0.25), b = jittered.nonzero_span(0.0, 0.25);
  ASSERT_TRUE(a && b);
  EXPECT_NEAR(a->first, b->first, kSample + 1e-9);
  EXPECT_NEAR(a->second, b->second, kSample + 1e-9);
  EXPECT_NEAR(jittered.zero_crossing_frequency_hz(0.35, 0.6), 50.0, 1.0);
}

// ---- multi-finger ----

TEST(RenderSpec, TwoFingersOnTwoDotsEachFireAtTheirOwnTimes) {
  const auto img = image_of({element("a", dot(30, 30, 2)), element("b", dot(30, 70, 2))});
  const auto r = render(img, gesture_of({line_stroke(10, 30, 50, 30, 100, 120, 0.0, 0),
                                         line_stroke(10, 70, 50, 70, 50, 120, 0.0, 1)}));
  // Finger 0 in the dot at 0.18..0.22 s; finger 1 at 0.36..0.44 s.
  const auto first = r.nonzero_span(0.0, 0.3), second = r.nonzero_span(0.3, 1.0);
  ASSERT_TRUE(first && second);
  EXPECT_NEAR(first->first, 0.18, kSample + 1e-9);
  EXPECT_NEAR(first->second, 0.22, kSample + 1e-9);
  EXPECT_NEAR(second->first, 0.36, kSample + 1e-9);
  EXPECT_NEAR(second->second, 0.44, kSample + 1e-9);
  EXPECT_NEAR(r.peak(0.36, 0.44), 0.5, 0.01);  // half speed: half strength
}

TEST(RenderSpec, SimultaneousContributionsAreSummedBeforeTheLimiter) {
  // Two fingers on one surface, in phase: the sum is twice one finger (below the knee).
  const auto img = image_of({element("s", rect_surface(0, 0, 100, 100, 2, 0.5, 0.2))});
  const auto one = render(img, gesture_of({line_stroke(10, 40, 90, 40, 100, 120, 0.0, 0)}));
  const auto two = render(img, gesture_of({line_stroke(10, 40, 90, 40, 100, 120, 0.0, 0),
                                           line_stroke(10, 60, 90, 60, 100, 120, 0.0, 1)}));
  ASSERT_EQ(one.d.size(), two.d.size());
  for (std::size_t i = 0; i < one.d.size(); i += 7) ASSERT_NEAR(two.d[i], 2.0f * one.d[i], 1e-6f) << i;
}

TEST(RenderSpec, RenderRateIsRespected) {
  const auto img = image_of({element("s", rect_surface(0, 0, 100, 100, 2, 0.5, 0.4))});
  for (const double rate : {1000.0, 8000.0, 48000.0}) {
    const auto r = render(img, gesture_of({line_stroke(10, 50, 90, 50, 100, 120, 0.0)}), rate);
    EXPECT_NEAR(static_cast<double>(r.d.size()) / rate, 0.8, 4.0 / rate + 1e-9);  // + the release steps
    EXPECT_NEAR(r.zero_crossing_frequency_hz(0.1, 0.7), 50.0, 1.5);
  }
}

}  // namespace
}  // namespace vimg
