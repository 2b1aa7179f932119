#include <gtest/gtest.h>

#include <filesystem>

#include "hal/output_spec.hpp"

namespace vimg {
namespace {

TEST(OutputSpec, ParsesEveryKind) {
  auto audio = parse_output_spec("audio");
  ASSERT_TRUE(audio.spec);
  EXPECT_TRUE(std::get<AudioOutput>(*audio.spec).device_name.empty());
  EXPECT_EQ(std::get<AudioOutput>(*parse_output_spec("audio:USB Audio").spec).device_name, "USB Audio");
  EXPECT_EQ(std::get<WavOutput>(*parse_output_spec("wav:/tmp/a.wav").spec).path, "/tmp/a.wav");

  const auto drv = parse_output_spec("drv2605l:/dev/i2c-1,en=gpiochip0:17,addr=0x5B,calibration=/tmp/c.txt");
  ASSERT_TRUE(drv.spec) << drv.error;
  const auto& d = std::get<Drv2605lOutput>(*drv.spec);
  EXPECT_EQ(d.bus, "/dev/i2c-1");
  ASSERT_TRUE(d.enable_pin);
  EXPECT_EQ(d.enable_pin->chip, "gpiochip0");
  EXPECT_EQ(d.enable_pin->line, 17u);
  EXPECT_EQ(d.address, 0x5B);
  EXPECT_EQ(d.calibration_file, "/tmp/c.txt");

  const auto spi = parse_output_spec("spi:/dev/spidev0.0,mode=1,speed=2000000");
  ASSERT_TRUE(spi.spec) << spi.error;
  EXPECT_EQ(std::get<SpiOutput>(*spi.spec).device, "/dev/spidev0.0");
  EXPECT_EQ(std::get<SpiOutput>(*spi.spec).mode, 1);
  EXPECT_EQ(std::get<SpiOutput>(*spi.spec).speed_hz, 2'000'000u);

  const auto hid = parse_output_spec("hid:04d8:f00a");
  ASSERT_TRUE(hid.spec) << hid.error;
  EXPECT_EQ(std::get<HidOutput>(*hid.spec).vendor_id, 0x04d8);
  EXPECT_EQ(std::get<HidOutput>(*hid.spec).product_id, 0xf00a);
}

TEST(OutputSpec, BadValuesNameTheOptionAndTheProblem) {
  for (const char* bad : {"wav:", "drv2605l:", "drv2605l:/dev/i2c-1,en=17", "drv2605l:/dev/i2c-1,addr=0x99",
                          "drv2605l:/dev/i2c-1,speed=1", "spi:", "spi:/dev/spidev0.0,mode=7", "hid:12345",
                          "hid:zz:01", "speaker"}) {
    const auto result = parse_output_spec(bad);
    EXPECT_FALSE(result.spec) << bad;
    EXPECT_EQ(result.error.rfind(std::string("--output ") + bad + ": ", 0), 0u) << result.error;
  }
}

TEST(OutputSpec, MissingDevicesAreErrorsNamingThem) {
  try {
    open_output(Drv2605lOutput{"/dev/i2c-does-not-exist", std::nullopt, 0x5A, ""}, default_lra_profile());
    FAIL();
  } catch (const std::exception& error) {
    EXPECT_NE(std::string(error.what()).find("/dev/i2c-does-not-exist"), std::string::npos) << error.what();
  }
  try {
    open_output(SpiOutput{"/dev/spidev-does-not-exist", 0, 1000000}, default_lra_profile());
    FAIL();
  } catch (const std::exception& error) {
    EXPECT_NE(std::string(error.what()).find("/dev/spidev-does-not-exist"), std::string::npos) << error.what();
  }
}

TEST(OutputSpec, WavOutputWritesAFile) {
  const auto path = std::filesystem::temp_directory_path() / "vimg_output_spec_test.wav";
  std::filesystem::remove(path);
  {
    auto output = open_output(WavOutput{path.string()}, default_lra_profile());
    output->sink().open(8000.0);
    const std::vector<float> block(64, 0.25f);
    output->sink().write(block, 0.0);
    output->sink().close();
    EXPECT_TRUE(output->take_messages().empty());
  }
  ASSERT_TRUE(std::filesystem::exists(path));
  EXPECT_GE(std::filesystem::file_size(path), 64u * 4u);
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace vimg
