// Probe paths against their limits (docs/limits.md, "Gestures and probe paths"): non-finite and
// absurd times and coordinates, too many rows and too long a path are refused with FILE:LINE, and
// the number of rows a render will produce can be checked before anything is reserved.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <string>

#include "storage/limits.hpp"
#include "storage/volume/probe_path_io.hpp"

namespace vimg {
namespace {

const std::string kHeader = "time_s,x_mm,y_mm,z_mm\n";

std::string first_message(const ProbePathParseResult& r) { return r.diagnostics.empty() ? "" : r.diagnostics[0].to_string(); }

TEST(ProbePathLimits, ValuesAtTheLimitsAreAccepted) {
  const ProbePathParseResult r = parse_probe_path_csv(
      kHeader + "-86000,-10000,0,10000\n-85400,10000,-10000,0\n", "p.csv");
  ASSERT_TRUE(r.path.has_value()) << first_message(r);
  EXPECT_EQ(r.path->size(), 2u);
  EXPECT_DOUBLE_EQ(r.path->back().position_m.x, 10.0);
}

TEST(ProbePathLimits, AbsurdTimesAreRefused) {
  EXPECT_EQ(first_message(parse_probe_path_csv(kHeader + "0,0,0,0\n1e300,0,0,0\n", "p.csv")),
            "p.csv:3: error: column 1 (time_s) '1e300' is beyond 86400 s (limit 86400)");
  EXPECT_EQ(first_message(parse_probe_path_csv(kHeader + "-86400.5,0,0,0\n", "p.csv")),
            "p.csv:2: error: column 1 (time_s) '-86400.5' is beyond 86400 s (limit 86400)");
}

TEST(ProbePathLimits, AbsurdCoordinatesAreRefused) {
  EXPECT_EQ(first_message(parse_probe_path_csv(kHeader + "0,1e300,0,0\n", "p.csv")),
            "p.csv:2: error: column 2 (x_mm) '1e300' is beyond 10000 mm (limit 10000)");
  EXPECT_EQ(first_message(parse_probe_path_csv(kHeader + "0,0,0,-10000.001\n", "p.csv")),
            "p.csv:2: error: column 4 (z_mm) '-10000.001' is beyond 10000 mm (limit 10000)");
}

TEST(ProbePathLimits, NonFiniteValuesAreRefused) {
  for (const char* bad : {"nan", "inf", "-inf", "1e999"}) {
    SCOPED_TRACE(bad);
    const ProbePathParseResult r = parse_probe_path_csv(kHeader + "0,0," + bad + ",0\n", "p.csv");
    EXPECT_FALSE(r.path.has_value());
    EXPECT_EQ(first_message(r).rfind("p.csv:2: error: column 3", 0), 0u) << first_message(r);
  }
}

TEST(ProbePathLimits, APathLongerThanTheDurationLimitIsRefused) {
  EXPECT_TRUE(parse_probe_path_csv(kHeader + "10,0,0,0\n610,0,0,0\n", "p.csv").path.has_value());
  const ProbePathParseResult r = parse_probe_path_csv(kHeader + "10,0,0,0\n300,0,0,0\n610.5,0,0,0\n700,0,0,0\n", "p.csv");
  EXPECT_FALSE(r.path.has_value());
  ASSERT_EQ(r.diagnostics.size(), 1u) << "reported once, at the first row past the limit";
  EXPECT_EQ(first_message(r), "p.csv:4: error: the path lasts more than 600 s (limit 600)");
}

TEST(ProbePathLimits, RowsBeyondTheRowLimitAreRefused) {
  std::string csv = kHeader;
  csv.reserve(kMaxProbePathRows * 16 + 64);
  for (std::size_t i = 0; i <= kMaxProbePathRows; ++i) csv += std::to_string(i) + "e-4,0,0,0\n";
  const ProbePathParseResult r = parse_probe_path_csv(csv, "p.csv");
  EXPECT_FALSE(r.path.has_value());
  ASSERT_EQ(r.diagnostics.size(), 1u);
  EXPECT_EQ(first_message(r), "p.csv:1000002: error: more than 1000000 rows (limit 1000000)");
}

TEST(ProbePathLimits, RenderRowsAreCheckedBeforeReserving) {
  EXPECT_EQ(probe_render_rows(1.0, 1000.0), std::optional<std::size_t>(1001));
  EXPECT_EQ(probe_render_rows(0.0, 1000.0), std::optional<std::size_t>(1));
  EXPECT_EQ(probe_render_rows(kMaxProbePathDurationS, kMaxDeviceRateHz), std::optional<std::size_t>(kMaxProbeRenderRows));
  EXPECT_FALSE(probe_render_rows(kMaxProbePathDurationS + 1.0, kMaxDeviceRateHz).has_value());
  EXPECT_FALSE(probe_render_rows(1e300, 1000.0).has_value());
  EXPECT_FALSE(probe_render_rows(1.0, 0.0).has_value());
  EXPECT_FALSE(probe_render_rows(1.0, std::nan("")).has_value());
  EXPECT_FALSE(probe_render_rows(-1.0, 1000.0).has_value());
}

}  // namespace
}  // namespace vimg
