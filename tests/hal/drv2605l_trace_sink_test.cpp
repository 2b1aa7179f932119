#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <vector>

#include "hal/drv2605l_trace_sink.hpp"
#include "hal/output_spec.hpp"
#include "player/drive_sinks.hpp"

namespace vimg {
namespace {

TEST(Drv2605lTraceSink, ForwardsTheDriveAndWritesTimedRegisterTraffic) {
  const auto path = std::filesystem::temp_directory_path() / "vimg_trace_sink_test.csv";
  std::filesystem::remove(path);
  MemorySink memory;
  {
    Drv2605lTraceSink sink(memory, default_lra_profile(), path);
    sink.open(8000.0);
    std::vector<float> block(80);
    for (int b = 0; b < 50; ++b) {
      for (std::size_t i = 0; i < block.size(); ++i) {
        block[i] = static_cast<float>(0.5 * std::sin(2.0 * std::numbers::pi * 175.0 * static_cast<double>(b * 80 + static_cast<int>(i)) / 8000.0));
      }
      sink.write(block, b * 0.01);
    }
    sink.close();
    EXPECT_FALSE(sink.error());
  }
  EXPECT_EQ(memory.samples().size(), 4000u);
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "time_s,op,register,value");
  double last_time = -1.0;
  int rtp = 0;
  std::string last;
  while (std::getline(in, line)) {
    std::istringstream row(line);
    std::string time, op, reg, value;
    std::getline(row, time, ',');
    std::getline(row, op, ',');
    std::getline(row, reg, ',');
    std::getline(row, value, ',');
    const double t = std::stod(time);
    EXPECT_GE(t, last_time);
    last_time = t;
    if (op == "write" && reg == "0x02") ++rtp;
    last = line;
  }
  EXPECT_GT(rtp, 0);
  EXPECT_GT(last_time, 0.45);  // follows the render's 0.5 s
  EXPECT_NE(last.find("write,0x01,0x40"), std::string::npos) << last;  // standby at the end
  std::filesystem::remove(path);
}

TEST(Drv2605lTraceSink, RefusesProfilesThatAreNotADrv2605lLra) {
  MemorySink memory;
  ActuatorProfile ideal;
  ideal.name = "ideal";
  EXPECT_THROW(Drv2605lTraceSink(memory, ideal, "/tmp/x.csv"), std::invalid_argument);
}

}  // namespace
}  // namespace vimg
