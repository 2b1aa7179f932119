// `vimg render --signal/--equalize`, `vimg validate --actuator` and `vimg info --actuator` on
// generated images and gestures (issue 14, "Done when"): what a designer would run.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include "run_command.hpp"

namespace vimg {
namespace {

namespace fs = std::filesystem;

const std::string kVimg = VIMG_BINARY_DIR "/cli/vimg";
const std::string kLra = VIMG_SOURCE_DIR "/assets/profiles/lra-175hz-drv2605l.xml";
const std::string kIdeal = VIMG_SOURCE_DIR "/assets/profiles/ideal.xml";

struct Series {
  std::string column;
  std::vector<double> time_s;
  std::vector<double> value;
};

class ActuatorCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("vimg_actuator_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    // A finger crossing the image at exactly fullSpeed (100 mm/s), firmly pressed.
    std::ofstream gesture(dir_ / "g.csv");
    gesture << "time_s,finger,x_mm,y_mm,pressure,phase\n0,0,5,20,1,down\n";
    for (int i = 1; i <= 90; ++i) gesture << i * 0.01 << ",0," << 5 + i << ",20,1,move\n";
    gesture << "0.91,0,95,20,1,up\n";
  }
  void TearDown() override { fs::remove_all(dir_); }

  // A 100 x 40 mm SURFACE felt at frequency_hz at fullSpeed; returns its path. Line 4 holds it.
  std::string surface_image(double frequency_hz) {
    const fs::path path = dir_ / ("s" + std::to_string(static_cast<int>(frequency_hz)) + ".vimg");
    std::ofstream(path) << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
                           "<vibroimage version=\"1.0\" width=\"100\" height=\"40\">\n"
                           "  <interaction mass=\"0.01\" fullSpeed=\"100\" maxDeformation=\"1\"/>\n"
                           "  <surface id=\"s\" shape=\"rect\" x=\"0\" y=\"0\" width=\"100\" height=\"40\" period=\""
                        << 100.0 / frequency_hz << "\" relief=\"0.5\" pattern=\"sine\" gain=\"0.5\"/>\n"
                           "</vibroimage>\n";
    return path.string();
  }

  test::CommandRun run(const std::string& arguments) {
    return test::run_command("cd '" + dir_.string() + "' && timeout 60 '" + kVimg + "' " + arguments);
  }

  Series render_csv(const std::string& image, const std::string& options) {
    const test::CommandRun r = run("render '" + image + "' --gesture g.csv --out out.csv " + options);
    EXPECT_EQ(r.exit_code, 0) << r.out;
    Series s;
    std::ifstream in(dir_ / "out.csv");
    std::string line;
    std::getline(in, line);
    s.column = line.substr(line.find(',') + 1);
    while (std::getline(in, line)) {
      const auto comma = line.find(',');
      s.time_s.push_back(std::stod(line.substr(0, comma)));
      s.value.push_back(std::stod(line.substr(comma + 1)));
    }
    return s;
  }

  std::string read(const std::string& name) {
    std::ifstream in(dir_ / name, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
  }

  fs::path dir_;
};

// Mean power in dB over the middle of the stroke (0.3-0.7 s: inside the surface, past the LRA's
// build-up of about Q / (pi f0) = 18 ms).
double rms_db(const Series& s) {
  double sum = 0.0;
  int n = 0;
  for (std::size_t i = 0; i < s.value.size(); ++i) {
    if (s.time_s[i] >= 0.3 && s.time_s[i] <= 0.7) {
      sum += s.value[i] * s.value[i];
      ++n;
    }
  }
  return 10.0 * std::log10(sum / n);
}

TEST_F(ActuatorCommand, OnTheLraA175HzSurfaceIsAtLeast6DbStrongerThanA60HzOne) {
  const Series at175 = render_csv(surface_image(175.0), "--actuator '" + kLra + "' --signal acceleration");
  const Series at60 = render_csv(surface_image(60.0), "--actuator '" + kLra + "' --signal acceleration");
  EXPECT_EQ(at175.column, "acceleration");
  // The drive of both is the same design intensity; the actuator makes the difference.
  const Series drive175 = render_csv(surface_image(175.0), "--actuator '" + kLra + "'");
  const Series drive60 = render_csv(surface_image(60.0), "--actuator '" + kLra + "'");
  EXPECT_NEAR(rms_db(drive175), rms_db(drive60), 0.5);
  EXPECT_GE(rms_db(at175) - rms_db(at60), 6.0) << rms_db(at175) << " vs " << rms_db(at60);
}

TEST_F(ActuatorCommand, EqualizeBrings120And175HzWithinThreeDbWithoutDrivingPastTheLimit) {
  const std::string lra = "--actuator '" + kLra + "' ";
  const Series plain120 = render_csv(surface_image(120.0), lra + "--signal acceleration");
  const Series plain175 = render_csv(surface_image(175.0), lra + "--signal acceleration");
  EXPECT_GT(std::fabs(rms_db(plain175) - rms_db(plain120)), 3.0);  // the resonance shows without it
  const Series eq120 = render_csv(surface_image(120.0), lra + "--signal acceleration --equalize");
  const Series eq175 = render_csv(surface_image(175.0), lra + "--signal acceleration --equalize");
  EXPECT_LE(std::fabs(rms_db(eq175) - rms_db(eq120)), 3.0) << rms_db(eq175) << " vs " << rms_db(eq120);
  for (const double f : {120.0, 175.0, 60.0}) {
    const Series drive = render_csv(surface_image(f), lra + "--signal drive --equalize");
    EXPECT_EQ(drive.column, "drive");
    // Bounded before the clamp: a clamped sample would be exactly 1 (docs/actuators.md: the
    // equalized drive of these surfaces peaks at 0.47).
    double peak = 0.0;
    int at_limit = 0;
    for (const double v : drive.value) {
      peak = std::max(peak, std::fabs(v));
      if (std::fabs(v) >= 1.0) ++at_limit;
    }
    EXPECT_LE(peak, 0.48) << f;
    EXPECT_GT(peak, 0.1) << f;
    EXPECT_EQ(at_limit, 0) << f;
  }
}

// The reference is the SURFACE's equation (DESIGN section 4), not another render: gain 0.5,
// pressed past its relief (clip 1), at fullSpeed (no fade), so 0.5 sin(2 pi 50 Hz t) while the
// finger moves (to 0.9 s; the phase starts at contact), then nothing (a still finger).
TEST_F(ActuatorCommand, WithoutTheNewFlagsTheDriveIsTheSurfacesEquation) {
  const std::string image = surface_image(50.0);  // a period of exactly 2 mm
  const std::string lra = "--actuator '" + kLra + "'";
  for (const std::string& options : {std::string(), lra, lra + " --signal drive"}) {
    const Series drive = render_csv(image, options);
    EXPECT_EQ(drive.column, "drive") << options;
    ASSERT_GT(drive.value.size(), 7200u) << options;
    for (std::size_t i = 0; i < drive.value.size(); ++i) {
      const double t = static_cast<double>(i) / 8000.0;  // the default rate; the file's times are rounded
      ASSERT_NEAR(drive.time_s[i], t, 1e-6) << i;
      const double expected = t <= 0.9 ? 0.5 * std::sin(2.0 * 3.141592653589793 * 50.0 * t) : 0.0;
      ASSERT_NEAR(drive.value[i], expected, 1e-6) << options << " at " << t << " s";
    }
  }
  ASSERT_EQ(run("render '" + image + "' --gesture g.csv --out plain.csv").exit_code, 0);
  EXPECT_EQ(read("plain.csv").rfind("time_s,drive\n", 0), 0u);
}

TEST_F(ActuatorCommand, OnTheIdealActuatorAccelerationIsTheDriveByteForByte) {
  const std::string image = surface_image(60.0);
  for (const std::string& profile : {std::string(), " --actuator '" + kIdeal + "'"}) {
    ASSERT_EQ(run("render '" + image + "' --gesture g.csv --out drive.wav" + profile).exit_code, 0);
    ASSERT_EQ(run("render '" + image + "' --gesture g.csv --out accel.wav --signal acceleration --equalize" + profile).exit_code, 0);
    EXPECT_EQ(read("drive.wav"), read("accel.wav"));
    EXPECT_GT(read("drive.wav").size(), 1000u);
  }
  const Series drive = render_csv(image, "--actuator '" + kIdeal + "'");
  const Series acceleration = render_csv(image, "--actuator '" + kIdeal + "' --signal acceleration");
  EXPECT_EQ(acceleration.column, "acceleration");
  EXPECT_EQ(drive.value, acceleration.value);
}

TEST_F(ActuatorCommand, ValidateWarnsAbout20HzOnTheLraAndNotAbout175Hz) {
  const std::string weak = surface_image(20.0);
  const test::CommandRun r = run("validate '" + weak + "' --actuator '" + kLra + "'");
  EXPECT_EQ(r.exit_code, 0) << r.out;  // warnings only
  const std::string prefix = weak + ":4: warning: surface 's' at 20 Hz (fullSpeed 100 mm/s / period 5 mm) is ";
  EXPECT_NE(r.out.find(prefix), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("outside its felt band 151-203 Hz (within 10 dB of the peak); a period of "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(weak + ": ok"), std::string::npos) << r.out;

  const std::string felt = surface_image(175.0);
  const test::CommandRun ok = run("validate '" + felt + "' --actuator '" + kLra + "'");
  EXPECT_EQ(ok.exit_code, 0) << ok.out;
  EXPECT_EQ(ok.out.find("warning"), std::string::npos) << ok.out;
  // Without --actuator nothing is said about the feel.
  EXPECT_EQ(run("validate '" + weak + "'").out.find("warning"), std::string::npos);
}

TEST_F(ActuatorCommand, ValidateWarnsAboutALineOutsideTheBandWithAFrequencyThatWouldBeFelt) {
  const fs::path path = dir_ / "line.vimg";
  std::ofstream(path) << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<vibroimage version=\"1.0\" width=\"100\" height=\"40\">\n"
                         "  <group id=\"g\">\n"
                         "    <line id=\"low\" x1=\"0\" y1=\"0\" x2=\"50\" y2=\"0\" width=\"2\" frequency=\"40\" damping=\"0.05\" gain=\"1\"/>\n"
                         "    <line id=\"ok\" x1=\"0\" y1=\"9\" x2=\"50\" y2=\"9\" width=\"2\" frequency=\"180\" damping=\"0.05\" gain=\"1\"/>\n"
                         "  </group>\n</vibroimage>\n";
  const test::CommandRun r = run("validate line.vimg --actuator '" + kLra + "'");
  EXPECT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("line.vimg:4: warning: line 'low' at 40 Hz is -32.4 dB on actuator 'lra-175hz-drv2605l'"), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("a frequency of 161 Hz would be felt"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("'ok'"), std::string::npos) << r.out;
}

TEST_F(ActuatorCommand, InfoListsEachPrimitivesFrequencyAndResponse) {
  const test::CommandRun r = run("info '" + surface_image(20.0) + "' --actuator '" + kLra + "'");
  EXPECT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("actuator:     lra-175hz-drv2605l (lra, felt band 151-203 Hz"), std::string::npos) << r.out;
  std::istringstream rows(r.out.substr(r.out.find("resp_dB")));
  std::string header, line_no, kind, id, frequency, db, weak;
  std::getline(rows, header);
  rows >> line_no >> kind >> id >> frequency >> db >> weak;
  EXPECT_EQ(line_no, "4");
  EXPECT_EQ(kind, "surface");
  EXPECT_EQ(frequency, "20");
  // The resonator's equation at 20 Hz, Q 10: -10 log10(1 + 100 (20/175 - 175/20)^2).
  const double x = 20.0 / 175.0 - 175.0 / 20.0;
  EXPECT_NEAR(std::stod(db), -10.0 * std::log10(1.0 + 100.0 * x * x), 0.1);
  EXPECT_EQ(weak, "weak");
}

TEST_F(ActuatorCommand, BadSignalOrProfileIsRefused) {
  const std::string image = surface_image(60.0);
  EXPECT_EQ(run("render '" + image + "' --gesture g.csv --out o.wav --signal velocity").exit_code, 2);
  EXPECT_EQ(run("render '" + image + "' --gesture g.csv --out o.wav --actuator '" + kLra +
                "' --signal acceleration --register-trace t.csv").exit_code, 2);
  std::ofstream(dir_ / "bad.xml") << "<actuator name=\"x\" type=\"lra\">\n  <resonance hz=\"175\"/>\n"
                                     "  <response model=\"lra\" q=\"0\"/>\n</actuator>\n";
  for (const std::string& command : {"validate '" + image + "'", "info '" + image + "'",
                                    "render '" + image + "' --gesture g.csv --out o.wav"}) {
    const test::CommandRun r = run(command + " --actuator bad.xml");
    EXPECT_EQ(r.exit_code, 1) << command << "\n" << r.out;
    EXPECT_NE(r.out.find("bad.xml:3: error: attribute 'q' must be in [0.5, 200], got 0"), std::string::npos) << r.out;
  }
  EXPECT_FALSE(fs::exists(dir_ / "o.wav"));
}

}  // namespace
}  // namespace vimg
