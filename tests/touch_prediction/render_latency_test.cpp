// `vimg render --touch-latency-ms` (player/simulated_panel.hpp through render_gesture): a late
// panel moves every felt LINE onset by about latency x speed, and the players' compensation brings
// the onsets back, on a curved path (bench/latency_scenario.hpp).
#include <gtest/gtest.h>

#include "bench/latency_scenario.hpp"

namespace vimg {
namespace {

using namespace latency_scenario;

TEST(RenderLatency, CompensationBringsTheFeltOnsetsBackOnACurvedPath) {
  const Gesture g = curved_swipe();
  const std::vector<double> exact = onsets(g, std::nullopt);
  ASSERT_EQ(exact.size(), 3u);
  for (double latency_s : {0.03, 0.06, 0.1}) {
    const double late = mean_onset_error_mm(exact, onsets(g, PanelSimulation{latency_s, false}), kSpeed_mm_per_s);
    const double compensated = mean_onset_error_mm(exact, onsets(g, PanelSimulation{latency_s, true}), kSpeed_mm_per_s);
    // Late: the panel's latency times the speed, within an event interval's travel.
    EXPECT_NEAR(late, kSpeed_mm_per_s * latency_s, kSpeed_mm_per_s / 60.0) << latency_s;
    // docs/latency.md: 4.2 -> 0.2 mm at 30 ms, 8.7 -> 1.6 mm at 60 ms, 14.7 -> 5.8 mm at 100 ms.
    EXPECT_LT(compensated, 0.5 * late) << latency_s;
  }
}

TEST(RenderLatency, AZeroLatencyPanelWithoutCompensationFeelsTheLinesWhereTheyAre) {
  const Gesture g = curved_swipe();
  const double error = mean_onset_error_mm(onsets(g, std::nullopt), onsets(g, PanelSimulation{0.0, false}), kSpeed_mm_per_s);
  EXPECT_LT(error, 0.5);
}

}  // namespace
}  // namespace vimg
