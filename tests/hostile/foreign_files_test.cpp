// Foreign and hostile files through `vimg validate`, `vimg info` and `vimg convert` (issue 13,
// "Done when"): a fixed sample of PNG, XML, DTD and SVG files made by other tools
// (tests/hostile/data/foreign, copied from what Debian installs under /usr/share: icons,
// documentation, XML catalogues; every PNG colour type) and the crafted files of tests/hostile/data
// (make_data.py). Every
// run exits 0 or 1 within a time bound, never crashes or hangs; exit 1 comes with
// `FILE[:LINE]: error: ...`; "no vibroimage chunk" is said only of a file without one; a failed
// convert leaves neither output nor temporary behind.
#include <gtest/gtest.h>

#include <cctype>
#include <sys/wait.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

const std::string kVimg = VIMG_BINARY_DIR "/cli/vimg";
const fs::path kData = VIMG_SOURCE_DIR "/tests/hostile/data";
const fs::path kForeign = VIMG_SOURCE_DIR "/tests/hostile/data/foreign";
constexpr double kBoundS = 20.0;  // per run, Debug build on a loaded 2-core machine

struct VimgRun {
  int exit_code = -1;  // -1: killed by a signal (a crash)
  double seconds = 0.0;
  std::string out;
};

std::string quoted(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

VimgRun run(const std::string& arguments) {
  VimgRun r;
  const auto start = std::chrono::steady_clock::now();
  // timeout(1) ends a hang with 124 (and a crash shows as 128 + signal through the shell).
  FILE* pipe = ::popen(("timeout " + std::to_string(static_cast<int>(kBoundS)) + " " + quoted(kVimg) + " " +
                        arguments + " 2>&1")
                           .c_str(),
                       "r");
  if (pipe == nullptr) return r;
  char buffer[4096];
  std::size_t n = 0;
  while ((n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0) r.out.append(buffer, n);
  const int status = ::pclose(pipe);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

std::string read_all(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

bool has_extension(const fs::path& p, std::initializer_list<const char*> extensions) {
  std::string e = p.extension().string();
  std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return std::any_of(extensions.begin(), extensions.end(), [&](const char* x) { return e == x; });
}

// The sample's files with one of the extensions, sorted.
std::vector<fs::path> foreign_files(std::initializer_list<const char*> extensions) {
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(kForeign)) {
    if (e.is_regular_file() && has_extension(e.path(), extensions)) files.push_back(e.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

// A line "…NAME: error: text" or "…NAME:LINE: error: text" (the file's name as given).
bool has_located_error(const std::string& out, const std::string& name) {
  std::size_t line_start = 0;
  while (line_start < out.size()) {
    std::size_t line_end = out.find('\n', line_start);
    if (line_end == std::string::npos) line_end = out.size();
    const std::string line = out.substr(line_start, line_end - line_start);
    for (std::size_t at = line.find(name); at != std::string::npos; at = line.find(name, at + 1)) {
      std::size_t i = at + name.size();
      if (i < line.size() && line[i] == ':' && i + 1 < line.size() && std::isdigit(static_cast<unsigned char>(line[i + 1]))) {
        ++i;
        while (i < line.size() && std::isdigit(static_cast<unsigned char>(line[i]))) ++i;
      }
      const std::string tag = ": error: ";
      if (line.compare(i, tag.size(), tag) == 0 && line.size() > i + tag.size()) return true;
    }
    line_start = line_end + 1;
  }
  return false;
}

// The checks every file gets; returns the validate run for further checks.
VimgRun check_file(const fs::path& file, const fs::path& scratch) {
  const std::string f = quoted(file.string());
  const VimgRun validate = run("validate " + f);
  const VimgRun info = run("info " + f);
  fs::remove_all(scratch);
  fs::create_directories(scratch);
  const fs::path out = scratch / (has_extension(file, {".png"}) ? "out.vimg" : "out.png");
  const VimgRun convert = run("convert " + f + " " + quoted(out.string()));
  for (const auto& [what, r] : {std::pair{"validate", &validate}, std::pair{"info", &info}, std::pair{"convert", &convert}}) {
    EXPECT_TRUE(r->exit_code == 0 || r->exit_code == 1) << what << " " << file << " exit " << r->exit_code << "\n" << r->out;
    EXPECT_LT(r->seconds, kBoundS) << what << " " << file;
    if (r->exit_code == 1) {
      // FILE: error: or FILE:LINE: error: (the file's name as given, escaped when it must be).
      EXPECT_TRUE(has_located_error(r->out, file.filename().string())) << what << " " << file << "\n" << r->out;
    }
  }
  const std::string bytes = read_all(file);
  const bool has_chunk = bytes.find(std::string("vibroimage\0", 11)) != std::string::npos;
  if (validate.out.find("no 'vibroimage' text chunk") != std::string::npos) {
    EXPECT_FALSE(has_chunk) << file << " holds a vibroimage chunk, yet: " << validate.out;
  }
  std::vector<std::string> left;
  for (const auto& e : fs::directory_iterator(scratch)) left.push_back(e.path().filename().string());
  if (convert.exit_code == 0) {
    EXPECT_EQ(left, std::vector<std::string>{out.filename().string()}) << file;
  } else {
    EXPECT_TRUE(left.empty()) << file << " left " << left.front();
  }
  return validate;
}

// One scratch folder per test: ctest runs the tests of this file in parallel, and each test
// empties its folder before every convert.
fs::path scratch_of_this_test() {
  return fs::path(VIMG_BINARY_DIR) / "hostile_foreign_files" / ::testing::UnitTest::GetInstance()->current_test_info()->name();
}

// The 13 PNGs are whole pictures of other tools: every chunk's CRC right, every colour type,
// no 'vibroimage' text chunk (tests/hostile/data/foreign/README.md; checked outside libpng, chunk by
// chunk with zlib's CRC-32). So validate must refuse each as a plain picture, and nothing else.
TEST(ForeignFiles, PngFilesOfOtherToolsNeverCrashOrHangAndSayWhatIsWrong) {
  const auto files = foreign_files({".png"});
  ASSERT_EQ(files.size(), 13u);
  for (const auto& file : files) {
    const VimgRun v = check_file(file, scratch_of_this_test());
    ASSERT_EQ(read_all(file).find("vibroimage"), std::string::npos) << file;
    EXPECT_EQ(v.exit_code, 1) << file << "\n" << v.out;
    EXPECT_NE(v.out.find(file.filename().string() + ": error: this PNG has no 'vibroimage' text chunk"), std::string::npos)
        << file << "\n" << v.out;
  }
}

TEST(ForeignFiles, XmlDtdAndSvgFilesOfOtherToolsNeverCrashOrHangAndSayWhatIsWrong) {
  const auto files = foreign_files({".xml", ".svg", ".dtd"});
  ASSERT_EQ(files.size(), 8u);
  for (const auto& file : files) {
    const VimgRun v = check_file(file, scratch_of_this_test());
    EXPECT_EQ(v.exit_code, 1) << file << " is not a vibroimage\n" << v.out;
  }
}

struct Crafted {
  const char* name;
  int exit_code;
  const char* message;  // a part of the validate output that names the problem
};

TEST(ForeignFiles, CraftedFilesGetTheMessageThatNamesTheirProblem) {
  const Crafted crafted[] = {
      {"interlaced-with-chunk.png", 0, ": ok"},
      {"sixteen-bit-with-chunk.png", 0, ": ok"},
      {"palette-with-chunk.png", 0, ": ok"},
      {"grey-alpha-with-chunk.png", 0, ": ok"},
      {"uncompressed-itxt-with-chunk.png", 0, ": ok"},
      {"ztxt-with-chunk.png", 0, ": ok"},
      {"utf8-bom.vimg", 0, ": ok"},
      {"grey-alpha-without-chunk.png", 1, "no 'vibroimage' text chunk"},
      {"palette-without-chunk.png", 1, "no 'vibroimage' text chunk"},
      {"truncated-in-idat.png", 1, "the file ends too early"},
      {"truncated-after-signature.png", 1, "the file ends too early"},
      {"bad-crc-ihdr.png", 1, "IHDR: CRC error"},
      {"bad-crc-vibroimage-chunk.png", 1, "'vibroimage' iTXt chunk is damaged (CRC mismatch)"},
      {"huge-dimensions.png", 1, "1000000 x 1000000 pixels, over the limit of 200000 pixels a side (limit 200000)"},
      {"huge-but-legal-dimensions.png", 1, "over the limit of 100000000 pixels decoded (limit 100000000)"},
      {"ztxt-bomb.png", 1, "inflates to more than 67108864 bytes (limit 67108864)"},
      {"itxt-bomb.png", 1, "inflates to more than 67108864 bytes (limit 67108864)"},
      {"two-vibroimage-chunks.png", 1, "holds 2 'vibroimage' text chunks"},
      {"chunk-longer-than-file.png", 1, "a chunk claims 2147483632 bytes"},
      {"not-xml-in-chunk.png", 1, "a NUL byte at offset 0 of its text"},
      {"doctype-billion-laughs.vimg", 1, ":2: error: a <!DOCTYPE> declaration"},
      {"external-entity.vimg", 1, ":2: error: a <!DOCTYPE> declaration"},
      {"deep-nesting.vimg", 1, "nested more than 64 deep (limit 64)"},
      {"utf16-bom.vimg", 1, ":1: error: the text is UTF-16"},
      {"latin1-bytes-declared-utf8.vimg", 1, "\"caf\\xE9\""},
      {"nul-in-the-middle.vimg", 1, ":3: error: a NUL byte at offset 95"},
      {"nul-only.vimg", 1, ":1: error: a NUL byte at offset 0"},
      {"empty.vimg", 1, "the file is empty"},
      {"unclosed-root.vimg", 1, ":3: error: the file ends before <vibroimage> (opened at line 2) is closed"},
      {"undefined-entity.vimg", 1, ":2: error: the entity '&eacute;' is not defined"},
      {"bare-ampersand.vimg", 1, ":2: error: a '&' that starts no reference ('& pepper'); write '&amp;'"},
      {"escape-sequence.vimg", 1, ":2: error: a control character (byte 0x1B) at offset 71, which XML does not allow"},
      {"reference-to-nul.vimg", 1, ":2: error: the character reference '&#0;' names a character XML does not allow"},
      {"lt-in-attribute.vimg", 1, ":2: error: a '<' inside the value of an attribute of <dot>; write '&lt;'"},
      {"dashes-in-comment.vimg", 1, ":2: error: '--' inside a comment"},
      {"declaration-not-first.vimg", 1, ":2: error: an XML declaration '<?xml ...?>' that is not at the very start"},
      {"mismatched-tag.vimg", 1, ":4: error: </grop> does not close <group> (opened at line 2)"},
      {"svg-not-a-vibroimage.svg", 1, "root element is <svg>, expected <vibroimage>"},
      {"nrrd-volume.nrrd", 1, "nrrd-volume.nrrd:1: error: not an image: this is a NRRD volume"},
      {"gesture-table.vimg", 1, "gesture-table.vimg:1: error: not an image: this is text that is not XML, starting with 'time_s,finger"},
      {"json-after-blank-lines.vimg", 1, "json-after-blank-lines.vimg:3: error: not an image: this is JSON"},
  };
  std::size_t in_folder = 0;
  for (const auto& e : fs::directory_iterator(kData)) in_folder += e.is_regular_file() ? 1 : 0;
  EXPECT_EQ(in_folder, std::size(crafted)) << "every crafted file has its expectation";
  for (const Crafted& c : crafted) {
    const VimgRun v = check_file(kData / c.name, scratch_of_this_test());
    EXPECT_EQ(v.exit_code, c.exit_code) << c.name << "\n" << v.out;
    EXPECT_NE(v.out.find(c.message), std::string::npos) << c.name << "\n" << v.out;
  }
}

TEST(ForeignFiles, AnAttributeOfEightMegabytesIsReadAndRefusedForWhatItIs) {
  fs::create_directories(scratch_of_this_test().parent_path());
  const fs::path file = fs::path(VIMG_BINARY_DIR) / "hostile_huge_attribute.vimg";
  std::ofstream(file) << "<vibroimage version=\"1.0\" width=\"10\" height=\"10\">\n<dot x=\"1\" y=\"1\" radius=\"1\" id=\""
                      << std::string(8u << 20, '7') << "\"/>\n</vibroimage>\n";
  const VimgRun v = check_file(file, scratch_of_this_test());
  EXPECT_EQ(v.exit_code, 1) << v.out;
  EXPECT_NE(v.out.find(":2: error: <dot> id \"7777"), std::string::npos) << v.out;
  EXPECT_LT(v.out.size(), 2000u) << "the value is quoted cut short, not 8 MB of it";
}

}  // namespace
