#include <gtest/gtest.h>

#include <random>

#include "hal/force/hid_force_device.hpp"
#include "hal/force/hid_force_emulator.hpp"
#include "hal/force/hid_force_finder.hpp"

namespace vimg {
namespace {

TEST(HidForceProtocol, ReportsRoundTripWithTheirResolution) {
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> pos(-0.5, 0.5), force(-30.0, 30.0);
  for (int i = 0; i < 1000; ++i) {
    hid_force::StateReport s{static_cast<std::uint8_t>(i), 0x5, 0x1, {pos(rng), pos(rng), pos(rng)}};
    const auto decoded = hid_force::decode_state(hid_force::encode_state(s));
    ASSERT_TRUE(decoded);
    EXPECT_EQ(decoded->sequence, s.sequence);
    EXPECT_EQ(decoded->buttons, 0x5);
    EXPECT_NEAR(decoded->position_m.x, s.position_m.x, 0.5e-6);
    EXPECT_NEAR(decoded->position_m.z, s.position_m.z, 0.5e-6);
    hid_force::ForceReport f{7, true, {force(rng), force(rng), force(rng)}};
    const auto df = hid_force::decode_force(hid_force::encode_force(f));
    ASSERT_TRUE(df);
    EXPECT_TRUE(df->enable);
    EXPECT_NEAR(df->force_N.y, f.force_N.y, 0.5e-3);
  }
  // Saturation instead of wrap-around.
  const auto big = hid_force::decode_force(hid_force::encode_force({0, true, {100.0, -100.0, 0.0}}));
  EXPECT_NEAR(big->force_N.x, 32.767, 1e-9);
  EXPECT_NEAR(big->force_N.y, -32.767, 1e-9);
}

TEST(HidForceProtocol, ByteLayoutIsLittleEndianAsDocumented) {
  const auto r = hid_force::encode_force({0x12, true, {0.001, -0.001, 1.0}});
  const std::array<std::uint8_t, 9> expected = {0x03, 0x12, 0x01, 0x01, 0x00, 0xFF, 0xFF, 0xE8, 0x03};
  EXPECT_EQ(r, expected);
  const auto s = hid_force::encode_state({1, 2, 3, {1e-6, -1e-6, 0.0}});
  EXPECT_EQ(s[0], 0x02);
  EXPECT_EQ(s[4], 0x01);
  EXPECT_EQ(s[8], 0xFF);
  EXPECT_EQ(s[11], 0xFF);
  EXPECT_FALSE(hid_force::decode_force(std::span<const std::uint8_t>(r.data(), 8)));
  EXPECT_FALSE(hid_force::decode_state(r));  // wrong report id
}

TEST(HidForceProtocol, InfoByte15IsTheSlewLimitInTenthsOfNewtonsPerMillisecond) {
  hid_force::DeviceInfo info;
  info.limits.max_slew_N_per_ms = 2.5;
  const auto r = hid_force::encode_info(info);
  EXPECT_EQ(r[15], 25);
  EXPECT_NEAR(hid_force::decode_info(r)->limits.max_slew_N_per_ms, 2.5, 1e-12);
  // Rounded to the unit, saturated at 25.5 N/ms, never 0 (which would mean "the default").
  info.limits.max_slew_N_per_ms = 0.36;
  EXPECT_EQ(hid_force::encode_info(info)[15], 4);
  info.limits.max_slew_N_per_ms = 1000.0;
  EXPECT_EQ(hid_force::encode_info(info)[15], 255);
  info.limits.max_slew_N_per_ms = 0.01;
  EXPECT_EQ(hid_force::encode_info(info)[15], 1);
  // A device from before the slew byte sends 0 there: the default.
  auto old = hid_force::encode_info({});
  old[15] = 0;
  const auto decoded = hid_force::decode_info(old);
  ASSERT_TRUE(decoded);
  EXPECT_EQ(decoded->limits.max_slew_N_per_ms, kDefaultMaxSlew_N_per_ms);
  EXPECT_NEAR(decoded->limits.max_force_N, 3.3, 1e-12);
  // The layout of the other fields is unchanged.
  const std::array<std::uint8_t, 16> v1 = {0x01, 0x01, 0xE4, 0x0C, 0x90, 0x01, 0xA0, 0x00,
                                           0x78, 0x00, 0x78, 0x00, 0xE8, 0x03, 0x02, 0x00};
  const auto from_v1 = hid_force::decode_info(v1);
  ASSERT_TRUE(from_v1);
  EXPECT_NEAR(from_v1->limits.max_force_N, 3.3, 1e-12);
  EXPECT_EQ(from_v1->limits.max_stiffness_N_per_m, 400.0);
  EXPECT_NEAR(from_v1->limits.workspace_m.x, 0.16, 1e-12);
  EXPECT_EQ(from_v1->report_rate_hz, 1000);
  EXPECT_EQ(from_v1->limits.max_slew_N_per_ms, kDefaultMaxSlew_N_per_ms);
}

hid_force::DeviceInfo diy_info() {
  hid_force::DeviceInfo info;
  info.limits = {2.5, 600.0, {0.15, 0.1, 0.08}, 0.8};
  info.report_rate_hz = 1000;
  info.button_count = 2;
  return info;
}

TEST(HidForceDevice, ReadsLimitsPositionAndButtonsAndSendsForces) {
  auto emulator = std::make_unique<HidForceEmulator>(diy_info());
  HidForceEmulator& device_side = *emulator;
  std::string error;
  auto device = HidForceDevice::open(std::move(emulator), error);
  ASSERT_TRUE(device) << error;
  EXPECT_NEAR(device->limits().max_force_N, 2.5, 1e-12);
  EXPECT_NEAR(device->limits().max_stiffness_N_per_m, 600.0, 1e-12);
  EXPECT_NEAR(device->limits().workspace_m.z, 0.08, 1e-12);
  EXPECT_NEAR(device->limits().max_slew_N_per_ms, 0.8, 1e-12);

  ProbeSample s;
  for (int i = 0; i <= 200; ++i) {
    const double t = i * 1e-3;
    device_side.set_position({0.05 * t, -0.01, 0.02});  // 50 mm/s along x
    device_side.set_buttons(i > 100 ? 1 : 0);
    device_side.emit_state();
    ASSERT_TRUE(device->read(t, s));
  }
  EXPECT_NEAR(s.position_m.x, 0.01, 1e-6);
  EXPECT_NEAR(s.position_m.y, -0.01, 1e-6);
  EXPECT_NEAR(s.velocity_m_per_s.x, 0.05, 0.002);
  EXPECT_EQ(s.buttons, 1u);

  ASSERT_TRUE(device->write_force({0.5, -0.25, 1.0}));
  EXPECT_NEAR(device_side.rendered_force_N().x, 0.5, 1e-3);
  EXPECT_NEAR(device_side.rendered_force_N().z, 1.0, 1e-3);
  // The host clamps to Fmax before sending.
  ASSERT_TRUE(device->write_force({10.0, 0.0, 0.0}));
  EXPECT_NEAR(device_side.received().back().force_N.x, 2.5, 1e-3);
  EXPECT_EQ(device_side.malformed_reports(), 0);
  // Sequence numbers count up.
  EXPECT_EQ(static_cast<std::uint8_t>(device_side.received()[1].sequence - device_side.received()[0].sequence), 1);
}


TEST(HidForceEmulator, WatchdogZeroesTheForceAfter50msWithoutReports) {
  HidForceEmulator device_side(diy_info());
  const auto r = hid_force::encode_force({0, true, {1.0, 0.0, 0.0}});
  device_side.write(r);
  device_side.advance_s(0.049);
  EXPECT_NEAR(device_side.rendered_force_N().x, 1.0, 1e-3);
  device_side.advance_s(0.002);
  EXPECT_EQ(device_side.rendered_force_N(), Vec3{});
  // enable = 0 renders nothing either.
  device_side.write(hid_force::encode_force({1, false, {1.0, 0.0, 0.0}}));
  EXPECT_EQ(device_side.rendered_force_N(), Vec3{});
}

class ForwardingTransport final : public HidTransport {
 public:
  explicit ForwardingTransport(HidForceEmulator& e) : e_(e) {}
  int write(std::span<const std::uint8_t> r) override { return e_.write(r); }
  int read(std::span<std::uint8_t> b, int t) override { return e_.read(b, t); }
  int get_feature_report(std::span<std::uint8_t> b) override { return e_.get_feature_report(b); }

 private:
  HidForceEmulator& e_;
};

TEST(HidForceDevice, DestructionSendsZeroWithEnableCleared) {
  HidForceEmulator device_side(diy_info());
  std::string error;
  auto device = HidForceDevice::open(std::make_unique<ForwardingTransport>(device_side), error);
  ASSERT_TRUE(device) << error;
  device->write_force({1.0, 0.0, 0.0});
  EXPECT_TRUE(device_side.enabled());
  device.reset();
  EXPECT_FALSE(device_side.enabled());
  EXPECT_EQ(device_side.rendered_force_N(), Vec3{});
  EXPECT_FALSE(device_side.received().back().enable);
}

TEST(HidForceDevice, ErrorsAreReported) {
  hid_force::DeviceInfo wrong = diy_info();
  wrong.version = 7;
  HidForceEmulator v7(wrong);
  std::string error;
  EXPECT_FALSE(HidForceDevice::open(std::make_unique<ForwardingTransport>(v7), error));
  EXPECT_EQ(error, "HID force device: unsupported protocol version 7 (expected 1)");

  HidForceEmulator device_side(diy_info());
  auto device = HidForceDevice::open(std::make_unique<ForwardingTransport>(device_side), error);
  ASSERT_TRUE(device);
  ProbeSample s;
  EXPECT_FALSE(device->read(0.0, s));  // no state report has ever arrived
  EXPECT_EQ(device->last_fault(), PortFault::no_data);
  device_side.emit_state();
  EXPECT_TRUE(device->read(0.001, s));
  device_side.set_fault(true);
  device_side.emit_state();
  EXPECT_FALSE(device->read(0.002, s));  // the device reports a fault
  EXPECT_EQ(device->last_fault(), PortFault::device_fault);
  device_side.unplug();
  EXPECT_FALSE(device->write_force({0.1, 0.0, 0.0}));
  EXPECT_EQ(device->last_fault(), PortFault::io_error);
  EXPECT_FALSE(device->read(0.003, s));
  EXPECT_EQ(device->last_fault(), PortFault::io_error);
}

TEST(HidForceDevice, TheSequenceCountsStateReportsSoASilentDeviceLooksStale) {
  HidForceEmulator device_side(diy_info());
  std::string error;
  auto device = HidForceDevice::open(std::make_unique<ForwardingTransport>(device_side), error);
  ASSERT_TRUE(device) << error;
  ProbeSample s;
  device_side.emit_state();
  ASSERT_TRUE(device->read(0.0, s));
  const std::uint64_t first = s.sequence;
  // No report since: the same sequence (no new position), however often the loop reads.
  ASSERT_TRUE(device->read(0.001, s));
  ASSERT_TRUE(device->read(0.002, s));
  EXPECT_EQ(s.sequence, first);
  // 300 reports, read in batches across the wrap of the u8 sequence byte: it counts every one.
  for (int batch = 0; batch < 10; ++batch) {
    for (int i = 0; i < 30; ++i) device_side.emit_state();
    ASSERT_TRUE(device->read(0.003 + batch * 1e-3, s));
  }
  EXPECT_EQ(s.sequence, first + 300);
}

TEST(HidForceSearch, OpensTheFirstDeviceThatAnswersTheProtocol) {
  HidForceEmulatorHost host;
  host.add_other_device({"/dev/hidraw0", 0x046d, 0xc52b, "USB Receiver"});
  host.add_locked_device({"/dev/hidraw1", 0x1209, 0x0001, "Locked"});
  hid_force::DeviceInfo v7 = diy_info();
  v7.version = 7;
  host.add_force_device({"/dev/hidraw2", 0x1209, 0x0002, "Future stick"}, v7);
  host.add_force_device({"/dev/hidraw3", 0x1209, 0x0003, "DIY force stick"}, diy_info());
  host.add_force_device({"/dev/hidraw4", 0x1209, 0x0004, "Second stick"}, diy_info());
  const HidForceSearch found = find_hid_force_device(host, "");
  ASSERT_TRUE(found.device) << found.report;
  EXPECT_EQ(found.opened.path, "/dev/hidraw3");
  EXPECT_NEAR(found.device->limits().max_force_N, 2.5, 1e-12);
  EXPECT_EQ(host.opens(), 4);  // hidraw4 is never tried
}

TEST(HidForceSearch, SaysWhatItFoundAndWhyNothingAnswered) {
  HidForceEmulatorHost host;
  host.add_other_device({"/dev/hidraw0", 0x046d, 0xc52b, "USB Receiver"});
  host.add_locked_device({"/dev/hidraw1", 0x1209, 0x0001, ""});
  hid_force::DeviceInfo v7 = diy_info();
  v7.version = 7;
  host.add_force_device({"/dev/hidraw2", 0x1209, 0x0002, "Future stick"}, v7);
  const HidForceSearch none = find_hid_force_device(host, "");
  EXPECT_FALSE(none.device);
  EXPECT_EQ(none.report,
            "no HID device answers the force protocol (info feature report 0x01, version 1); found:\n"
            "  046d:c52b /dev/hidraw0 \"USB Receiver\": cannot read the device info report (0x01)\n"
            "  1209:0001 /dev/hidraw1: cannot open /dev/hidraw1: no read/write permission (see the udev rule in docs/volume-force-device.md)\n"
            "  1209:0002 /dev/hidraw2 \"Future stick\": unsupported protocol version 7 (expected 1)");

  // A named path: only that one.
  const HidForceSearch named = find_hid_force_device(host, "/dev/hidraw2");
  EXPECT_FALSE(named.device);
  EXPECT_EQ(named.report,
            "the device does not answer the force protocol (info feature report 0x01, version 1):\n"
            "  1209:0002 /dev/hidraw2 \"Future stick\": unsupported protocol version 7 (expected 1)");
  const HidForceSearch missing = find_hid_force_device(host, "/dev/hidraw9");
  EXPECT_EQ(missing.report,
            "the device does not answer the force protocol (info feature report 0x01, version 1):\n"
            "  /dev/hidraw9: cannot open /dev/hidraw9: No such file or directory");

  HidForceEmulatorHost empty;
  const HidForceSearch nothing = find_hid_force_device(empty, "");
  EXPECT_FALSE(nothing.device);
  EXPECT_NE(nothing.report.find("no HID device is visible"), std::string::npos) << nothing.report;
  EXPECT_NE(nothing.report.find("udev rule in docs/volume-force-device.md"), std::string::npos) << nothing.report;
}

TEST(HidForceSearch, StopsTryingWhenTheTimeBudgetIsSpent) {
  HidForceEmulatorHost host;
  host.add_other_device({"/dev/hidraw0", 0x046d, 0xc52b, "USB Receiver"});
  host.add_force_device({"/dev/hidraw1", 0x1209, 0x0003, "DIY force stick"}, diy_info());
  const HidForceSearch late = find_hid_force_device(host, "", -1.0);  // already spent
  EXPECT_FALSE(late.device);
  EXPECT_EQ(host.opens(), 0);
  EXPECT_NE(late.report.find("/dev/hidraw1 \"DIY force stick\": not tried: the search ran out of time"), std::string::npos)
      << late.report;
}

}  // namespace
}  // namespace vimg
