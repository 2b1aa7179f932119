// `vimg separate` as a designer runs it: help, a distinct set left alone, usage errors, bad input
// and signals (the full-size example cases run in Release: tests/separate_examples/).
#include "tests/separate/separate_fixture.hpp"

namespace vimg::separate_test {
namespace {

TEST_F(SeparateCommand, HelpAndVersionExitZero) {
  const auto help = vimg("separate --help");
  EXPECT_EQ(help.exit_code, 0);
  for (const char* option : {"--actuator", "--out", "--target", "--vary", "--keep", "--model"})
    EXPECT_NE(help.out.find(option), std::string::npos) << option;
  EXPECT_EQ(vimg("separate --version").exit_code, 0);
}

TEST_F(SeparateCommand, ADistinctSetWritesNothing) {
  texture("fine.vimg", 0.5, 40, 40);
  texture("coarse.vimg", 8.0, 40, 40);
  const auto r = vimg("separate fine.vimg coarse.vimg --out proposal");
  EXPECT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("nothing to change, nothing written"), std::string::npos) << r.out;
  EXPECT_FALSE(fs::exists(dir_ / "proposal"));
}

TEST_F(SeparateCommand, UsageErrorsExitTwoAndWriteNothing) {
  texture("a.vimg", 1.0, 20, 20);
  texture("b.vimg", 1.1, 20, 20);
  const std::pair<std::string, std::string> cases[] = {
      {"separate a.vimg --out p", "at least two images"},
      {"separate a.vimg b.vimg --out p --target 1.5", "--target must be in (0, 1)"},
      {"separate a.vimg b.vimg --out p --target 0", "--target must be in (0, 1)"},
      {"separate a.vimg b.vimg --out p --vary period,width", "unknown parameter 'width'"},
      {"separate a.vimg b.vimg --out p --keep c.vimg", "--keep 'c.vimg' is not one of the images"},
      {"separate a.vimg b.vimg --out .", "would write over the input"},
      {"separate a.vimg b.vimg", "--out"},
  };
  for (const auto& [args, message] : cases) {
    const auto r = vimg(args);
    EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.out;
    EXPECT_NE(r.out.find(message), std::string::npos) << args << "\n" << r.out;
  }
  EXPECT_FALSE(fs::exists(dir_ / "p"));
}

TEST_F(SeparateCommand, BadInputExitsOneWithFileAndLine) {
  texture("a.vimg", 1.0, 20, 20);
  std::ofstream(dir_ / "broken.vimg") << "<?xml version=\"1.0\"?>\n<vibroimage version=\"1.0\" width=\"20\" height=\"20\">\n<dot x=\"1\"/>\n</vibroimage>\n";
  const auto broken = vimg("separate a.vimg broken.vimg --out p");
  EXPECT_EQ(broken.exit_code, 1) << broken.out;
  EXPECT_NE(broken.out.find("broken.vimg:3: error:"), std::string::npos) << broken.out;
  const auto missing = vimg("separate a.vimg missing.vimg --out p");
  EXPECT_EQ(missing.exit_code, 1) << missing.out;
  EXPECT_NE(missing.out.find("missing.vimg"), std::string::npos) << missing.out;
  texture("b.vimg", 1.1, 20, 20);
  std::ofstream(dir_ / "bad_profile.xml") << "<actuator>\n";
  const auto actuator = vimg("separate a.vimg b.vimg --out p --actuator bad_profile.xml");
  EXPECT_EQ(actuator.exit_code, 1) << actuator.out;
  EXPECT_NE(actuator.out.find("bad_profile.xml"), std::string::npos) << actuator.out;
  std::ofstream(dir_ / "model.json") << "{";
  const auto model = vimg("separate a.vimg b.vimg --out p --model model.json");
  EXPECT_EQ(model.exit_code, 1) << model.out;
  EXPECT_NE(model.out.find("model.json:1: error:"), std::string::npos) << model.out;
  std::ofstream(dir_ / "file") << "x";
  const auto file = vimg("separate a.vimg b.vimg --out file");
  EXPECT_EQ(file.exit_code, 1) << file.out;
  EXPECT_NE(file.out.find("file: error: --out must be a folder"), std::string::npos) << file.out;
  EXPECT_FALSE(fs::exists(dir_ / "p"));
}

// Interrupted while it renders (it has said so: a state, not a time): exit 128 + signal, nothing
// written, no temporary left.
TEST_F(SeparateCommand, AnInterruptedSearchWritesNothing) {
  std::string inputs;
  for (int i = 0; i < 12; ++i) inputs += " " + texture("t" + std::to_string(i) + ".vimg", 2.0 + 0.05 * i, 300, 300);
  for (const auto& [signal_name, expected] : {std::pair{"INT", 130}, std::pair{"TERM", 143}}) {
    const std::string cmd = "cd '" + dir_.string() + "' && ('" + kVimg + "' separate" + inputs +
                            " --out p 2>err.txt & pid=$!; until grep -q 'rendering the set' err.txt; do "
                            "kill -0 $pid 2>/dev/null || break; sleep 0.01; done; kill -" + signal_name +
                            " $pid; wait $pid; status=$?; cat err.txt; rm -f err.txt; exit $status)";
    const auto r = test::run_command(cmd);
    EXPECT_EQ(r.exit_code, expected) << r.out;
    EXPECT_NE(r.out.find("interrupted"), std::string::npos) << r.out;
    EXPECT_FALSE(fs::exists(dir_ / "p"));
  }
}

}  // namespace
}  // namespace vimg::separate_test
