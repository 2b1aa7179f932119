#pragma once
// The fixture of `vimg separate`'s command tests (separate_command_test.cpp here, and the full-size
// examples in tests/separate_examples/): a scratch folder, the command run as a user runs it, the
// reports read back.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "storage/json_reader.hpp"
#include "tests/cli/run_command.hpp"

namespace vimg::separate_test {

namespace fs = std::filesystem;

inline const std::string kVimg = VIMG_BINARY_DIR "/cli/vimg";
inline const std::string kExamples = VIMG_SOURCE_DIR "/assets/examples/separate/";
inline const std::string kLra = VIMG_SOURCE_DIR "/assets/profiles/lra-175hz-drv2605l.xml";
inline const std::string kFour = kExamples + "texture_2_0mm.vimg " + kExamples + "texture_2_2mm.vimg " + kExamples +
                          "texture_2_4mm.vimg " + kExamples + "texture_2_6mm.vimg";

inline std::string read_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

inline JsonValue read_json(const fs::path& p) {
  JsonParseResult r = parse_json(read_text(p), p.string());
  EXPECT_TRUE(r.value.has_value()) << p;
  return r.value ? *r.value : JsonValue{};
}

class SeparateCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("vimg_separate_cmd_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  test::CommandRun vimg(const std::string& args) {
    return test::run_command("cd '" + dir_.string() + "' && timeout 300 '" + kVimg + "' " + args);
  }
  std::string texture(const std::string& name, double period_mm, double width_mm = 60, double height_mm = 110) {
    std::ostringstream s;
    s << "<?xml version=\"1.0\"?>\n<vibroimage version=\"1.0\" width=\"" << width_mm << "\" height=\"" << height_mm
      << "\">\n  <surface id=\"t\" shape=\"rect\" x=\"1\" y=\"1\" width=\"" << width_mm - 2 << "\" height=\""
      << height_mm - 2 << "\" period=\"" << period_mm << "\" relief=\"0.5\" pattern=\"sine\" gain=\"0.8\"/>\n</vibroimage>\n";
    std::ofstream(dir_ / name) << s.str();
    return name;
  }
  fs::path dir_;
};

// The diagonal of `vimg compare`'s predicted confusion.
inline std::vector<double> compare_diagonal(const JsonValue& report) {
  std::vector<double> out;
  const JsonValue* m = report.find("predicted_confusion");
  if (!m) return out;
  for (std::size_t i = 0; i < m->items.size(); ++i) out.push_back(m->items[i].items[i].number);
  return out;
}

}  // namespace vimg::separate_test
