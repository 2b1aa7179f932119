// What `vimg compare` reports as ST-SIM, against its definition in docs/perception.md ("Perceptual
// similarity"): stsim[i][j] is ST-SIM of input i against reference j over the blocks where either is
// felt, bounded to [0, 1], so that a designer reads it on the scale of the similarity beside it, and
// the similarity is (1 - v (1 - S)) L with S = min(stsim[i][j], stsim[j][i]). The plain metric, which
// runs far past 1 against a reference that is only a fading ring, is kept as `stsim_plain` in the
// JSON. The inputs are signals written here, so the expectations are computed from the same samples
// with the perception model's parts (ST-SIM over chosen blocks, the sensation levels), not from the
// report's code.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "primitives/perception/perceptual_similarity.hpp"
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

double bounded(double v) { return std::isnan(v) ? 0.0 : std::clamp(v, 0.0, 1.0); }

std::vector<std::vector<double>> matrix_of(const JsonValue& root, const char* key) {
  std::vector<std::vector<double>> m;
  const JsonValue* value = root.find(key);
  EXPECT_NE(value, nullptr) << key;
  if (!value) return m;
  for (const auto& row : value->items) {
    m.emplace_back();
    for (const auto& cell : row.items) m.back().push_back(cell.number);
  }
  return m;
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

TEST_F(CompareStSim, TheReportsShowStSimAsTheSimilarityTakesItAndTheJsonKeepsThePlainMetric) {
  // a: the tone; b: the same tone a sixth of a cycle later (the same levels, another waveform);
  // c: the tone for half a second, then its fading ring, where a is still felt.
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
  const auto plain = matrix_of(*parsed.value, "stsim_plain");
  const auto similarity = matrix_of(*parsed.value, "similarity");
  ASSERT_EQ(stsim.size(), 3u);
  ASSERT_EQ(plain.size(), 3u);
  ASSERT_EQ(similarity.size(), 3u);

  // The definition, from the samples as vimg compare reads them (floats at 8 kHz).
  std::vector<PerceptualFeatures> f;
  for (const auto& x : signals) f.push_back(analyse(std::vector<double>(x.begin(), x.end())));
  const SimilarityConstants constants;
  for (std::size_t i = 0; i < 3; ++i) {
    for (std::size_t j = 0; j < 3; ++j) {
      if (i == j) {
        EXPECT_EQ(stsim[i][j], 1.0);
        continue;
      }
      const std::size_t blocks = std::min(f[i].stsim.blocks, f[j].stsim.blocks);
      std::vector<std::uint8_t> felt(blocks);
      for (std::size_t k = 0; k < blocks; ++k) felt[k] = (f[i].levels.felt_block[k] | f[j].levels.felt_block[k]) != 0;
      const auto over_felt = stsim_over_blocks(f[i].stsim, f[j].stsim, felt);
      ASSERT_TRUE(over_felt.has_value());
      EXPECT_GE(stsim[i][j], 0.0) << i << "," << j;
      EXPECT_LE(stsim[i][j], 1.0) << i << "," << j;
      EXPECT_NEAR(stsim[i][j], bounded(over_felt->value), 1e-12) << i << "," << j;
      EXPECT_NEAR(plain[i][j], stsim_common_length(f[i].stsim, f[j].stsim)->value, 1e-9 * std::max(1.0, std::fabs(plain[i][j])))
          << i << "," << j;
      // similarity = (1 - v (1 - S)) L: S the smaller direction, v = min(1, felt / 10 dB),
      // L = 2^(-D / 20 dB), D the largest difference of felt level over the bands.
      const double s = std::min(stsim[i][j], stsim[j][i]);
      const double v = std::min(1.0, std::max(f[i].levels.max_felt_db(), f[j].levels.max_felt_db()) / constants.full_structure_db);
      double d = 0.0;
      for (std::size_t band = 0; band < kSensationBands; ++band) {
        d = std::max(d, std::fabs(f[i].levels.felt_db(band) - f[j].levels.felt_db(band)));
      }
      EXPECT_NEAR(similarity[i][j], (1.0 - v * (1.0 - s)) * std::exp2(-d / constants.level_halving_db), 1e-12) << i << "," << j;
    }
  }
  // The case that made the report unreadable: a against the fading ring of c runs past 1 in the
  // plain metric; the report shows 1, and the pair's structure is c's direction, below 1.
  EXPECT_GT(plain[0][2], 1.0);
  EXPECT_EQ(stsim[0][2], 1.0);
  EXPECT_LT(stsim[2][0], 1.0);
  // The same tone shifted: a structure between nothing and the same waveform.
  EXPECT_GT(stsim[0][1], 0.0);
  EXPECT_LT(stsim[0][1], 0.9);

  // The CSV's stsim column is the JSON's.
  std::istringstream csv(read_text(dir_ / "r.csv"));
  std::string line;
  std::getline(csv, line);
  EXPECT_EQ(line, "image_i,image_j,stsim,similarity,predicted_p");
  for (std::size_t row = 0; std::getline(csv, line); ++row) {
    ASSERT_LT(row, 9u);
    std::vector<std::string> cells;
    std::stringstream cut(line);
    for (std::string cell; std::getline(cut, cell, ',');) cells.push_back(cell);
    ASSERT_EQ(cells.size(), 5u) << line;
    EXPECT_EQ(std::stod(cells[2]), stsim[row / 3][row % 3]) << line;
  }
  // The page says what the numbers mean, and its ST-SIM table holds only numbers in [0, 1].
  const std::string html = read_text(dir_ / "r.html");
  EXPECT_NE(html.find("1 the same waveform, 0 nothing in common"), std::string::npos);
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
    EXPECT_GE(v, 0.0);
    EXPECT_LE(v, 1.0);
    ++numbers;
  }
  EXPECT_EQ(numbers, 9);
}

}  // namespace
}  // namespace vimg
