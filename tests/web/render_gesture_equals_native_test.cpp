// renderGesture (the page's offline render, in WebAssembly under Node) equals `vimg render IMAGE
// --gesture G --out F.csv [--actuator P]` within 1e-5 of full scale (issue 22, docs/web.md). Needs
// the web build (cmake --preset web && cmake --build --preset web) and Node; skipped with a message
// when either is absent.
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "tests/storage/storage_test_support.hpp"
#include "tests/web/web_test_support.hpp"
#include "web/site_builder/web_site.hpp"

namespace vimg {
namespace {

const std::filesystem::path kSite = VIMG_WEB_ASSETS_DIR;

std::string shell_quoted(const std::filesystem::path& p) { return "'" + p.string() + "'"; }

int run(const std::string& command) {
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

class RenderGestureEqualsNative : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!std::filesystem::exists(kSite / "vimg.wasm"))
      GTEST_SKIP() << "no web build in " << kSite << ": cmake --preset web && cmake --build --preset web";
    if (run("node --version > /dev/null 2>&1") != 0) GTEST_SKIP() << "node is not installed";
  }

  // Writes the .vsc with the site builder, renders natively with the CLI, compares under Node.
  void expect_equal(const std::string& image, const std::string& gesture, const std::string& profile) {
    test::TempDir dir("web_render");
    const auto src = test::source_dir();
    std::vector<std::string> profile_errors;
    const auto options = web_site_options(profile.empty() ? std::string() : (src / "assets/profiles" / profile).string(), profile_errors);
    ASSERT_TRUE(options) << (profile_errors.empty() ? "" : profile_errors.front());
    const auto diagnostics = update_web_image(src / "assets/examples" / image, *options, dir.path());
    ASSERT_FALSE(has_errors(diagnostics));
    const auto vsc = dir.path() / "images" / (web_image_name(image) + ".vsc");
    const auto native_csv = dir.path() / "native.csv";
    std::string render = shell_quoted(std::filesystem::path(VIMG_BINARY_DIR) / "cli/vimg") + " render " +
                         shell_quoted(src / "assets/examples" / image) + " --gesture " + shell_quoted(src / "assets/gestures" / gesture) +
                         " --out " + shell_quoted(native_csv);
    if (!profile.empty()) render += " --actuator " + shell_quoted(options.actuator_profile);
    ASSERT_EQ(run(render), 0) << render;
    const std::string compare = "node " + shell_quoted(src / "web/tests/render_gesture_equals_native.mjs") + " " + shell_quoted(kSite) +
                                " " + shell_quoted(vsc) + " " + shell_quoted(src / "assets/gestures" / gesture) + " " + shell_quoted(native_csv);
    EXPECT_EQ(run(compare), 0) << compare;
  }
};

TEST_F(RenderGestureEqualsNative, SmileyCircleIdealActuator) {
  expect_equal("smiley.vimg", "smiley_circle_240hz.csv", "");
}

TEST_F(RenderGestureEqualsNative, SmileyTwoFingersOnTheLraProfile) {
  expect_equal("smiley.vimg", "smiley_two_fingers.csv", "lra-175hz-drv2605l.xml");
}

TEST_F(RenderGestureEqualsNative, SmileyEyesOnTheVoiceCoilProfile) {
  expect_equal("smiley.vimg", "smiley_eyes.csv", "voice-coil-audio.xml");
}

}  // namespace
}  // namespace vimg
