#pragma once
// The files the fit's command tests make: SURFACE images on a small canvas (quick to render under
// the standard exploration), a matching study over them, and a test folder of its own.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace vimg::fit_test {

namespace fs = std::filesystem;

struct Surface {
  std::string stem;
  double period_mm = 2.0;
  double gain = 0.7;
};

// A canvas of canvas_mm x canvas_mm covered by one sine SURFACE.
inline void write_surface_image(const fs::path& dir, const Surface& s, double canvas_mm) {
  std::ofstream(dir / (s.stem + ".vimg"))
      << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<vibroimage version=\"1.0\" width=\"" << canvas_mm << "\" height=\""
      << canvas_mm << "\">\n  <surface id=\"s\" shape=\"rect\" x=\"0\" y=\"0\" width=\"" << canvas_mm << "\" height=\""
      << canvas_mm << "\" period=\"" << s.period_mm << "\" relief=\"0.5\" pattern=\"sine\" gain=\"" << s.gain
      << "\"/>\n</vibroimage>\n";
}

// study.xml in `dir`: one set `set_name` of the surfaces (written beside it), `repetitions` each.
inline fs::path write_surface_study(const fs::path& dir, const std::string& set_name, const std::vector<Surface>& surfaces,
                                    int repetitions, double canvas_mm) {
  fs::create_directories(dir);
  std::ostringstream xml;
  xml << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<matchingStudy version=\"1\" seed=\"2024\" repetitions=\"" << repetitions
      << "\" trainingMinutes=\"0\">\n  <set name=\"" << set_name << "\">\n";
  for (const Surface& s : surfaces) {
    write_surface_image(dir, s, canvas_mm);
    xml << "    <image file=\"" << s.stem << ".vimg\"/>\n";
  }
  xml << "  </set>\n</matchingStudy>\n";
  std::ofstream(dir / "study.xml") << xml.str();
  return dir / "study.xml";
}

inline std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// A fresh folder for the running test under the system's temporary folder, removed afterwards.
class FitFolderTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("vimg_study_fit_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override {
    if (!HasFailure()) fs::remove_all(dir_);
  }
  fs::path dir_;
};

}  // namespace vimg::fit_test
