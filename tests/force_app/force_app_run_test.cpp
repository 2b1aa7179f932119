// vimg-force itself, over a fresh study data set: the acceptance runs of docs/volume-force-device.md ("Feel it
// with a force device") and the project's exit-status convention.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <thread>

#include "storage/number_text.hpp"
#include "tests/child_process.hpp"
#include "storage/volume/volume_scene_io.hpp"

namespace vimg {
namespace {

namespace fs = std::filesystem;

const fs::path kVimg = fs::path(VIMG_BINARY_DIR) / "cli" / "vimg";
const fs::path kForce = fs::path(VIMG_BINARY_DIR) / "apps" / "force" / "vimg-force";

struct ProgramRun {
  int exit_code = -1;
  bool signalled_when_ready = false;  // ready() held when the signal was sent
  std::string out, err;
  double seconds = 0.0;
};

std::string read_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Runs the program in `dir`, stdout and stderr captured; sends `signal_number` once `ready()` holds
// (polled every millisecond: the program's state, never a fixed time; given up after 60 s).
ProgramRun run(const fs::path& program, const std::vector<std::string>& args, const fs::path& dir, int signal_number = 0,
               const std::function<bool()>& ready = {}) {
  const fs::path capture = dir.parent_path() / (dir.filename().string() + "_capture");
  fs::create_directories(capture);
  const std::string out_file = (capture / "stdout").string(), err_file = (capture / "stderr").string();
  test::ChildSpec spec;
  spec.argv = {program.string()};
  spec.argv.insert(spec.argv.end(), args.begin(), args.end());
  spec.dir = dir;
  spec.stdout_file = out_file;
  spec.stderr_file = err_file;
  const auto start = std::chrono::steady_clock::now();
  const pid_t pid = test::spawn_child(spec);
  ProgramRun r;
  EXPECT_GT(pid, 0) << "fork failed: " << std::strerror(errno);
  if (pid <= 0) return r;
  if (signal_number != 0) {
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (ready && !ready() && std::chrono::steady_clock::now() < give_up) {
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    r.signalled_when_ready = !ready || ready();
    test::signal_child(pid, signal_number);
  }
  const int status = test::reap_child(pid);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  r.out = read_text(out_file);
  r.err = read_text(err_file);
  return r;
}

std::vector<std::string> split(const std::string& text, char sep) {
  std::vector<std::string> parts;
  std::string part;
  std::istringstream in(text);
  while (std::getline(in, part, sep)) parts.push_back(part);
  return parts;
}

double number(const std::string& text) {
  const ParsedNumber v = parse_decimal(text);
  EXPECT_TRUE(std::holds_alternative<double>(v)) << "'" << text << "'";
  return std::holds_alternative<double>(v) ? std::get<double>(v) : NAN;
}

// "key":VALUE from the one-object telemetry JSON (numbers, or strings without escapes).
std::string json_value(const std::string& json, const std::string& key) {
  const std::string tag = "\"" + key + "\":";
  const std::size_t at = json.find(tag);
  if (at == std::string::npos) return "<missing " + key + ">";
  std::size_t begin = at + tag.size();
  if (json[begin] == '"') {
    const std::size_t end = json.find('"', begin + 1);
    return json.substr(begin + 1, end - begin - 1);
  }
  const std::size_t end = json.find_first_of(",}", begin);
  return json.substr(begin, end - begin);
}

// The rows the running program has written to the temporary of its log `name` in `dir` so far (the
// log writer drains the loop's ring into it while the loop runs).
std::size_t rows_being_logged(const fs::path& dir, const std::string& name) {
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    if (!it->path().filename().string().starts_with("." + name + ".tmp-")) continue;
    const std::string text = read_text(it->path());
    const auto lines = static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
    return lines > 0 ? lines - 1 : 0;  // without the header
  }
  return 0;
}

std::vector<std::string> files_in(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

class ForceApp : public ::testing::Test {
 protected:
  // Each test its own folder and study data set: ctest runs the tests in parallel processes.
  void SetUp() override {
    root_ = fs::path(VIMG_BINARY_DIR) / "test_output" / "force_app" /
            ::testing::UnitTest::GetInstance()->current_test_info()->name();
    fs::remove_all(root_);
    fs::create_directories(root_);
    const ProgramRun study = run(kVimg, {"volume", "make-study", "--seed", "1", "--out", "S"}, root_);
    ASSERT_EQ(study.exit_code, 0) << study.err;
    // A probe path crossing the study volume (x +-80, y +-60, z +-60 mm) diagonally and back.
    std::ofstream(root_ / "P.csv") << "time_s,x_mm,y_mm,z_mm\n0,-70,-20,-50\n1,70,20,50\n2,-70,0,0\n";
  }
  // A fresh folder for one run's outputs, holding nothing else.
  fs::path run_dir(const std::string& name) const {
    const fs::path dir = root_ / name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
  }
  std::string scene() const { return (root_ / "S" / "study.vscene.xml").string(); }
  std::string path() const { return (root_ / "P.csv").string(); }

  // The log's rows (without the header): every |F| within the clamp, the last one zero with the
  // given flag. Returns the number of rows.
  static std::size_t check_log(const fs::path& log, double clamp_N, const std::string& last_flags) {
    const std::vector<std::string> lines = split(read_text(log), '\n');
    EXPECT_GE(lines.size(), 2u);
    if (lines.size() < 2) return 0;
    EXPECT_EQ(lines[0], "time_s,x_mm,y_mm,z_mm,fx_N,fy_N,fz_N,flags");
    double last_time = -1.0;
    for (std::size_t i = 1; i < lines.size(); ++i) {
      const std::vector<std::string> f = split(lines[i] + ",", ',');  // keep an empty flags field
      EXPECT_EQ(f.size(), 8u) << lines[i];
      if (f.size() != 8u) return 0;
      const double t = number(f[0]);
      EXPECT_GT(t, last_time) << lines[i];
      last_time = t;
      const Vec3 force{number(f[4]), number(f[5]), number(f[6])};
      EXPECT_LE(norm(force), clamp_N + 1e-9) << lines[i];
    }
    const std::vector<std::string> last = split(lines.back() + ",", ',');
    EXPECT_EQ(number(last[4]), 0.0);
    EXPECT_EQ(number(last[5]), 0.0);
    EXPECT_EQ(number(last[6]), 0.0);
    EXPECT_EQ(last[7], last_flags);
    return lines.size() - 1;
  }

  fs::path root_;
};

// The rate the loop achieves is the machine's (bench/volume_bench.cpp, BM_ForceLoop); here the
// loop's logic: the scene's rate asked for, every logged cycle on that rate's schedule.
TEST_F(ForceApp, TheAcceptanceRunRunsOnTheScenesScheduleWithinTheClampAndEndsAtZero) {
  const auto loaded = load_volume_scene_file(scene());
  ASSERT_TRUE(loaded.ok());
  const DeviceProfile& device = loaded.loaded->scene.device;
  const fs::path dir = run_dir("accept");
  const ProgramRun r = run(kForce, {scene(), "--device", "sim", "--path", path(), "--seconds", "2", "--log", "F.csv", "--telemetry", "T.json"}, dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string t = read_text(dir / "T.json");
  EXPECT_EQ(number(json_value(t, "target_rate_hz")), device.rate_hz);
  EXPECT_GT(number(json_value(t, "rate_hz")), 0.0) << t;
  const double clamp = number(json_value(t, "clamp_N"));
  EXPECT_LE(clamp, device.max_force_N);
  EXPECT_LE(number(json_value(t, "max_force_N")), clamp);
  EXPECT_EQ(json_value(t, "exit_reason"), "seconds elapsed");
  EXPECT_EQ(json_value(t, "device_state"), "stopped");
  for (const char* key : {"jitter_p50_us", "jitter_p99_us", "jitter_max_us", "overruns", "cycles", "clamp_hits", "log_rows_dropped"}) {
    EXPECT_GE(number(json_value(t, key)), 0.0) << key;
  }
  EXPECT_EQ(json_value(t, "log_rows_dropped"), "0");
  const std::size_t rows = check_log(dir / "F.csv", clamp, "stop");
  EXPECT_EQ(std::to_string(rows), json_value(t, "cycles"));
  // Each cycle's time is a deadline, a whole number of periods after the start (later when the loop
  // skipped), and the run ends after its 2 s of loop time.
  const std::vector<std::string> lines = split(read_text(dir / "F.csv"), '\n');
  double last_s = 0.0;
  for (std::size_t i = 1; i < lines.size(); ++i) {
    const double periods = number(split(lines[i], ',')[0]) * device.rate_hz;
    ASSERT_NEAR(periods, std::round(periods), 1e-6) << lines[i];
    last_s = number(split(lines[i], ',')[0]);
  }
  EXPECT_GE(last_s, 2.0 - 5.0 / device.rate_hz);  // (the stop may come while the loop catches up)
  EXPECT_EQ(files_in(dir), (std::vector<std::string>{"F.csv", "T.json"}));
}

TEST_F(ForceApp, SigintPutsTheDeviceAtRestCompletesTheFilesAndExits130) {
  const fs::path dir = run_dir("sigint");
  // Signalled once more than 500 cycles are in the log being written.
  const ProgramRun r = run(kForce, {scene(), "--device", "sim", "--path", path(), "--log", "F.csv", "--telemetry", "T.json"}, dir,
                           SIGINT, [&] { return rows_being_logged(dir, "F.csv") > 500; });
  ASSERT_TRUE(r.signalled_when_ready) << "the log never held 500 rows while the loop ran";
  EXPECT_EQ(r.exit_code, 130) << r.err;
  const std::string t = read_text(dir / "T.json");
  EXPECT_EQ(json_value(t, "exit_reason"), "SIGINT") << t;
  const std::size_t rows = check_log(dir / "F.csv", number(json_value(t, "clamp_N")), "stop");
  EXPECT_GT(rows, 500u);
  EXPECT_EQ(std::to_string(rows), json_value(t, "cycles"));
  EXPECT_EQ(files_in(dir), (std::vector<std::string>{"F.csv", "T.json"}));  // no temporary file left
}

TEST_F(ForceApp, SigtermPutsTheDeviceAtRestCompletesTheFilesAndExits143) {
  const fs::path dir = run_dir("sigterm");
  const ProgramRun r = run(kForce, {scene(), "--device", "sim", "--log", "F.csv", "--telemetry", "T.json"}, dir, SIGTERM,
                           [&] { return rows_being_logged(dir, "F.csv") > 500; });
  ASSERT_TRUE(r.signalled_when_ready) << "the log never held 500 rows while the loop ran";
  EXPECT_EQ(r.exit_code, 143) << r.err;
  const std::string t = read_text(dir / "T.json");
  EXPECT_EQ(json_value(t, "exit_reason"), "SIGTERM") << t;
  const std::size_t rows = check_log(dir / "F.csv", number(json_value(t, "clamp_N")), "stop");
  EXPECT_GT(rows, 500u);
  EXPECT_EQ(files_in(dir), (std::vector<std::string>{"F.csv", "T.json"}));
}

TEST_F(ForceApp, AHidDeviceThatIsNotThereExitsOneWithinFiveSecondsSayingWhy) {
  const fs::path dir = run_dir("hid");
  const ProgramRun any = run(kForce, {scene(), "--device", "hid", "--seconds", "1", "--log", "F.csv"}, dir);
  EXPECT_EQ(any.exit_code, 1) << any.err;
  EXPECT_LT(any.seconds, 5.0);
  // "no HID device is visible (... udev rule ...)" here; where HID devices exist, each one that
  // did not answer the protocol, and why.
  EXPECT_EQ(any.err.rfind("vimg-force: error: no HID device", 0), 0u) << any.err;
  const ProgramRun named = run(kForce, {scene(), "--device", "hid:/dev/hidraw-none"}, dir);
  EXPECT_EQ(named.exit_code, 1);
  EXPECT_NE(named.err.find("/dev/hidraw-none: cannot open /dev/hidraw-none"), std::string::npos) << named.err;
  EXPECT_TRUE(files_in(dir).empty());  // nothing was started, nothing written
}

TEST_F(ForceApp, UsageErrorsExitTwoHelpAndVersionZero) {
  const fs::path dir = run_dir("usage");
  for (const std::vector<std::string>& args : std::vector<std::vector<std::string>>{
           {},
           {scene()},
           {scene(), "--device", "usb"},
           {scene(), "--device", "hid", "--path", path()},
           {scene(), "--device", "sim", "--seconds", "nan"}}) {
    const ProgramRun r = run(kForce, args, dir);
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_EQ(r.err.rfind("vimg-force: error: ", 0), 0u) << r.err;
  }
  const ProgramRun help = run(kForce, {"--help"}, dir);
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_NE(help.out.find("130 after SIGINT"), std::string::npos) << help.out;
  EXPECT_NE(help.out.find("143 after SIGTERM"), std::string::npos) << help.out;
  EXPECT_EQ(run(kForce, {"--version"}, dir).exit_code, 0);
}

TEST_F(ForceApp, BadInputExitsOneNamingFileAndLine) {
  const fs::path dir = run_dir("bad");
  std::ofstream(dir / "bad.vscene.xml") << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<volumeScene version=\"1.0\">\n"
                                           "  <device rate=\"50\"/>\n</volumeScene>\n";
  const ProgramRun scene_error = run(kForce, {"bad.vscene.xml", "--device", "sim", "--seconds", "1"}, dir);
  EXPECT_EQ(scene_error.exit_code, 1);
  EXPECT_EQ(scene_error.err.rfind("bad.vscene.xml:3: error: ", 0), 0u) << scene_error.err;

  std::ofstream(dir / "bad.csv") << "time_s,x_mm,y_mm,z_mm\n0,0,0,0\n0,1,0,0\n";
  const ProgramRun path_error = run(kForce, {scene(), "--device", "sim", "--path", "bad.csv", "--seconds", "1"}, dir);
  EXPECT_EQ(path_error.exit_code, 1);
  EXPECT_EQ(path_error.err.rfind("bad.csv:3: error: ", 0), 0u) << path_error.err;

  const ProgramRun no_folder = run(kForce, {scene(), "--device", "sim", "--seconds", "1", "--log", "missing/F.csv"}, dir);
  EXPECT_EQ(no_folder.exit_code, 1);
  EXPECT_EQ(no_folder.err.rfind("missing/F.csv: error: ", 0), 0u) << no_folder.err;
}

}  // namespace
}  // namespace vimg
