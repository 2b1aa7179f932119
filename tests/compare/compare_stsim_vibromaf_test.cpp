// The ST-SIM that `vimg compare` reports, pinned to numbers from outside this code: vibromaf's
// (tests/data/stsim/cases.csv, README.md there). Each case's distorted and reference signals are
// built from their recipes (tests/perception/fixture_signals.cpp), written as 32-bit float WAV files
// at 8 kHz, compared by the command, and the report's stsim of the distorted against the reference
// must be the reference's number. Cases: those where the reference returns a value for two signals
// of one length (the command compares over the common length; the reference refuses shorter ones)
// and neither holds a constant block: there the temporal term correlates rounding noise, which the
// command's 32-bit float samples change (dc_blocks_both: 0.535 against 0.592 on doubles).
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "storage/json_reader.hpp"
#include "tests/cli/run_command.hpp"
#include "tests/perception/fixture_signals.hpp"

namespace vimg {
namespace {

namespace fs = std::filesystem;

const std::string kVimg = VIMG_BINARY_DIR "/cli/vimg";

void put_u32(std::string& out, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) out.push_back(static_cast<char>((v >> (8 * i)) & 0xFFu));
}
void put_u16(std::string& out, std::uint16_t v) {
  out.push_back(static_cast<char>(v & 0xFFu));
  out.push_back(static_cast<char>(v >> 8));
}

// RIFF/WAVE, mono, IEEE float (format 3), 8000 Hz: the layout of the WAVE format, written here.
void write_float_wav(const fs::path& file, const std::vector<double>& x) {
  std::string data;
  for (const double v : x) {
    const auto f = static_cast<float>(v);
    std::uint32_t bits = 0;
    std::memcpy(&bits, &f, 4);
    put_u32(data, bits);
  }
  std::string wav = "RIFF";
  put_u32(wav, static_cast<std::uint32_t>(36 + data.size()));
  wav += "WAVEfmt ";
  put_u32(wav, 16);
  put_u16(wav, 3);
  put_u16(wav, 1);
  put_u32(wav, 8000);
  put_u32(wav, 8000 * 4);
  put_u16(wav, 4);
  put_u16(wav, 32);
  wav += "data";
  put_u32(wav, static_cast<std::uint32_t>(data.size()));
  wav += data;
  std::ofstream(file, std::ios::binary) << wav;
}

std::string read_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(CompareStSimVibromaf, TheReportedStSimIsTheReferenceImplementationsNumber) {
  const std::string data = VIMG_TEST_DATA_DIR "/stsim/";
  const auto signals = test::load_fixture_signals(data + "signals.csv");
  std::map<std::string, std::string> recipes;
  for (const auto& row : test::read_csv_rows(data + "signals.csv")) recipes[row.at("name")] = row.at("recipe");
  const fs::path dir = fs::temp_directory_path() / ("vimg_compare_vibromaf_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  int checked = 0;
  for (const auto& row : test::read_csv_rows(data + "cases.csv")) {
    if (row.at("result") != "value" || std::stod(row.at("eta")) != 2.0 / 3.0) continue;
    const auto& distorted = signals.at(row.at("distorted"));
    const auto& reference = signals.at(row.at("reference"));
    if (distorted.size() != reference.size() || distorted.size() < 512) continue;
    if (recipes.at(row.at("distorted")).find("const:") != std::string::npos ||
        recipes.at(row.at("reference")).find("const:") != std::string::npos) {
      continue;
    }
    write_float_wav(dir / "distorted.wav", distorted);
    write_float_wav(dir / "reference.wav", reference);
    const test::CommandRun run = test::run_command("cd '" + dir.string() + "' && '" + kVimg +
                                                   "' compare distorted.wav reference.wav --out r.json");
    ASSERT_EQ(run.exit_code, 0) << row.at("case") << ": " << run.out;
    const auto parsed = parse_json(read_text(dir / "r.json"), "r.json");
    ASSERT_TRUE(parsed.value) << row.at("case");
    const JsonValue* stsim = parsed.value->find("stsim");
    ASSERT_NE(stsim, nullptr);
    ASSERT_EQ(stsim->items.size(), 2u);
    const double reported = stsim->items[0].items[1].number;
    const double expected = std::stod(row.at("stsim"));
    // The samples pass through 32-bit floats; the reference computed on doubles.
    EXPECT_NEAR(reported, expected, 1e-6 * std::max(1.0, std::fabs(expected))) << row.at("case");
    ++checked;
  }
  fs::remove_all(dir);
  EXPECT_GE(checked, 10);
}

}  // namespace
}  // namespace vimg
