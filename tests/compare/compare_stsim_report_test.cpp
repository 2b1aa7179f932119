// What `vimg compare` reports as ST-SIM and what decides its prediction (docs/perception.md):
// stsim[i][j] is ST-SIM of input i against reference j over their common length, the metric as the
// reference implementation computes it (stsim_common_length, held to vibromaf by
// tests/perception/stsim_reference_test.cpp), in the JSON, the CSV and the HTML alike; the
// predicted confusion is the discrimination model's, so a tone and the same tone shifted in phase,
// whose ST-SIM is far below 1, are predicted confused half the time (phase is not felt), and the
// confusion is the choice rule over the reported distances. The inputs are signals written here, so
// the expectations are computed from the same samples with the model's parts, not from the
// report's code.
#include <gtest/gtest.h>

#include "primitives/perception/identification_choice.hpp"
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "primitives/perception/discrimination_choice.hpp"
#include "primitives/perception/stsim.hpp"
#include "storage/json_reader.hpp"
#include "tests/cli/run_command.hpp"

namespace vimg {
namespace {

namespace fs = std::filesystem;

const std::string kVimg = VIMG_BINARY_DIR "/cli/vimg";
constexpr double kRateHz = 8000.0;
constexpr double kPi = 3.14159265358979323846;

// Two seconds at 8 kHz of a 250 Hz tone at half scale: `phase` shifts it; from `ring_from_s` on it
// decays with a 0.1 s time constant, a ring that fades below threshold but never reaches zero.
std::vector<float> tone(double phase, double ring_from_s = 1e9) {
  std::vector<float> x(16000);
  for (std::size_t n = 0; n < x.size(); ++n) {
    const double t = static_cast<double>(n) / kRateHz;
    const double envelope = t < ring_from_s ? 1.0 : std::exp(-(t - ring_from_s) / 0.1);
    x[n] = static_cast<float>(0.5 * envelope * std::sin(2.0 * kPi * 250.0 * t + phase));
  }
  return x;
}

void write_signal_csv(const fs::path& file, const std::vector<float>& x) {
  std::ofstream out(file);
  out << "time_s,acceleration\n";
  char line[96];
  for (std::size_t n = 0; n < x.size(); ++n) {
    std::snprintf(line, sizeof line, "%.17g,%.9g\n", static_cast<double>(n) / kRateHz, static_cast<double>(x[n]));
    out << line;
  }
}

std::string read_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<std::vector<double>> matrix_of_value(const JsonValue* value, const char* key) {
  std::vector<std::vector<double>> m;
  EXPECT_NE(value, nullptr) << key;
  if (!value) return m;
  for (const auto& row : value->items) {
    m.emplace_back();
    for (const auto& cell : row.items) m.back().push_back(cell.number);
  }
  return m;
}

std::vector<std::vector<double>> matrix_of(const JsonValue& root, const char* key) {
  return matrix_of_value(root.find(key), key);
}

class CompareStSim : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("vimg_compare_stsim_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_F(CompareStSim, TheReportsShowThePlainMetricAndTheConfusionIsTheDiscriminationModels) {
  // a: the tone; b: the same tone a sixth of a cycle later (the same levels, another waveform);
  // c: the tone for half a second, then its fading ring.
  const std::vector<std::vector<float>> signals{tone(0.0), tone(kPi / 3.0), tone(0.0, 0.5)};
  const std::vector<std::string> names{"a.csv", "b.csv", "c.csv"};
  for (std::size_t i = 0; i < 3; ++i) write_signal_csv(dir_ / names[i], signals[i]);
  for (const char* out : {"r.json", "r.csv", "r.html"}) {
    const test::CommandRun run =
        test::run_command("cd '" + dir_.string() + "' && '" + kVimg + "' compare a.csv b.csv c.csv --out " + out);
    ASSERT_EQ(run.exit_code, 0) << run.out;
  }
  const auto parsed = parse_json(read_text(dir_ / "r.json"), "r.json");
  ASSERT_TRUE(parsed.value);
  const auto stsim = matrix_of(*parsed.value, "stsim");
  const auto distance = matrix_of(*parsed.value, "distance_jnd");
  const auto confusion = matrix_of(*parsed.value, "predicted_confusion");
  ASSERT_EQ(stsim.size(), 3u);
  ASSERT_EQ(distance.size(), 3u);
  ASSERT_EQ(confusion.size(), 3u);
  const JsonValue* cues = parsed.value->find("cue_distances_jnd");
  ASSERT_NE(cues, nullptr);

  // The definitions, from the samples as vimg compare reads them (floats at 8 kHz).
  std::vector<StSimFeatures> st;
  std::vector<DiscriminationFeatures> df;
  for (const auto& x : signals) {
    const std::vector<double> wide(x.begin(), x.end());
    st.push_back(analyse_stsim(wide));
    df.push_back(analyse_discrimination(wide));
  }
  CueMatrix expected_cues(3, std::vector<CueDistances>(3, CueDistances{}));
  for (std::size_t i = 0; i < 3; ++i) {
    for (std::size_t j = 0; j < 3; ++j) {
      if (i == j) {
        EXPECT_EQ(stsim[i][j], 1.0);
        continue;
      }
      EXPECT_NEAR(stsim[i][j], stsim_common_length(st[i], st[j])->value, 1e-9 * std::max(1.0, std::fabs(stsim[i][j])))
          << i << "," << j;
      expected_cues[i][j] = cue_distances(df[i], df[j]);
      for (std::size_t c = 0; c < kCueCount; ++c) {
        const auto per_cue = matrix_of_value(cues->find(std::string(cue_name(c))), "a cue");
        ASSERT_EQ(per_cue.size(), 3u);
        EXPECT_NEAR(per_cue[i][j], expected_cues[i][j][c], 1e-9) << cue_name(c);
      }
      EXPECT_NEAR(distance[i][j], combined_distance_jnd(expected_cues[i][j]), 1e-9);
    }
  }
  const PerceptionMatrix expected = identification_confusion(expected_cues);
  for (std::size_t i = 0; i < 3; ++i) {
    for (std::size_t j = 0; j < 3; ++j) EXPECT_NEAR(confusion[i][j], expected[i][j], 1e-9) << i << "," << j;
  }
  // ST-SIM no longer decides: the phase-shifted tone has a waveform far from a's, yet it is felt
  // alike (a and b split their rows evenly against each other, c's fading ring stands apart).
  EXPECT_LT(stsim[0][1], 0.9);
  EXPECT_NEAR(confusion[0][1], confusion[0][0], 0.05);
  // Against a reference that is only a fading ring the metric runs past 1; the report keeps it.
  EXPECT_GT(stsim[0][2], 1.0);

  // The CSV's columns are the JSON's.
  std::istringstream csv(read_text(dir_ / "r.csv"));
  std::string line;
  std::getline(csv, line);
  EXPECT_EQ(line, "image_i,image_j,stsim,level_jnd,pitch_jnd,envelope_jnd,distance_jnd,predicted_p");
  for (std::size_t row = 0; std::getline(csv, line); ++row) {
    ASSERT_LT(row, 9u);
    std::vector<std::string> cells;
    std::stringstream cut(line);
    for (std::string cell; std::getline(cut, cell, ',');) cells.push_back(cell);
    ASSERT_EQ(cells.size(), 8u) << line;
    const std::size_t i = row / 3, j = row % 3;
    EXPECT_EQ(std::stod(cells[2]), stsim[i][j]) << line;
    for (std::size_t c = 0; c < kCueCount; ++c) EXPECT_NEAR(std::stod(cells[3 + c]), expected_cues[i][j][c], 1e-9) << line;
    EXPECT_EQ(std::stod(cells[6]), distance[i][j]) << line;
    EXPECT_EQ(std::stod(cells[7]), confusion[i][j]) << line;
  }
  // The page says what ST-SIM is and shows the same numbers.
  const std::string html = read_text(dir_ / "r.html");
  EXPECT_NE(html.find("It does not decide the prediction"), std::string::npos);
  EXPECT_NE(html.find("Values far above 1 (up to millions) are the metric's own"), std::string::npos)
      << "the page says why ST-SIM runs above 1";
  const std::size_t table = html.find("<th class=\"name\">ST-SIM of");
  ASSERT_NE(table, std::string::npos);
  const std::string cells = html.substr(table, html.find("</table>", table) - table);
  // Every plain <td>...</td> cell (std::regex is avoided: GCC 12 at -O1 warns inside <regex>).
  int numbers = 0;
  for (std::size_t at = cells.find("<td>"); at != std::string::npos; at = cells.find("<td>", at + 1)) {
    const std::size_t begin = at + 4;
    const std::size_t end = cells.find("</td>", begin);
    ASSERT_NE(end, std::string::npos);
    const double v = std::stod(cells.substr(begin, end - begin));
    EXPECT_NEAR(v, stsim[static_cast<std::size_t>(numbers) / 3][static_cast<std::size_t>(numbers) % 3],
                5e-4 * std::max(1.0, std::fabs(v)));
    ++numbers;
  }
  EXPECT_EQ(numbers, 9);
}

}  // namespace
}  // namespace vimg
