// `vimg render --touch-latency-ms` (player/simulated_panel.hpp through render_gesture): a late
// panel moves every felt LINE onset by about latency x speed, and the players' compensation brings
// the onsets back, on a curved path (bench/latency_scenario.hpp). Each LINE is felt once, late or
// compensated: as many felt onsets as exact ones.
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
    const std::vector<double> late_onsets = onsets(g, PanelSimulation{latency_s, false});
    const std::vector<double> compensated_onsets = onsets(g, PanelSimulation{latency_s, true});
    // One felt onset per LINE crossed, as exact: a render that buzzes on and off near a LINE would
    // have an onset near each exact one and still be wrong.
    EXPECT_EQ(late_onsets.size(), exact.size()) << latency_s;
    EXPECT_EQ(compensated_onsets.size(), exact.size()) << latency_s;
    const double late = mean_onset_error_mm(exact, late_onsets, kSpeed_mm_per_s);
    const double compensated = mean_onset_error_mm(exact, compensated_onsets, kSpeed_mm_per_s);
    // Late: the panel's latency times the speed, within an event interval's travel.
    EXPECT_NEAR(late, kSpeed_mm_per_s * latency_s, kSpeed_mm_per_s / 60.0) << latency_s;
    // docs/latency.md: 4.2 -> 0.2 mm at 30 ms, 8.7 -> 1.6 mm at 60 ms, 14.7 -> 5.8 mm at 100 ms.
    EXPECT_LT(compensated, 0.5 * late) << latency_s;
  }
}

TEST(RenderLatency, AZeroLatencyPanelWithoutCompensationFeelsTheLinesWhereTheyAre) {
  const Gesture g = curved_swipe();
  const std::vector<double> exact = onsets(g, std::nullopt), felt = onsets(g, PanelSimulation{0.0, false});
  EXPECT_EQ(felt.size(), exact.size());
  EXPECT_LT(mean_onset_error_mm(exact, felt, kSpeed_mm_per_s), 0.5);
}

}  // namespace
}  // namespace vimg
