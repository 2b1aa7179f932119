// Messages about hostile input: whatever a file holds, a diagnostic is printable text of bounded
// length (control characters, C1 controls and bytes that are not UTF-8 shown as \xNN, cut at
// kMaxMessageBytes), and a file reports at most kMaxDiagnosticsPerFile diagnostics plus one line
// counting the rest (docs/limits.md, "Messages").
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "storage/diagnostic.hpp"
#include "storage/image_io.hpp"
#include "storage/limits.hpp"
#include "storage/volume/nrrd.hpp"
#include "storage/volume/probe_path_io.hpp"
#include "storage/volume/volume_scene_io.hpp"

namespace vimg {
namespace {

// True when `text` holds no byte a terminal could act on: no ASCII control (0-31, 127) and no C1
// control (U+0080-U+009F, UTF-8 C2 80 - C2 9F), and every byte >= 0x80 is part of valid UTF-8.
bool terminal_safe(const std::string& text) {
  const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(text[i]); };
  for (std::size_t i = 0; i < text.size();) {
    const unsigned char b = byte(i);
    if (b < 0x20 || b == 0x7F) return false;
    if (b < 0x80) {
      ++i;
      continue;
    }
    const std::size_t n = b >= 0xF0 ? 4 : b >= 0xE0 ? 3 : b >= 0xC2 ? 2 : 0;
    if (n == 0 || b > 0xF4 || i + n > text.size()) return false;
    for (std::size_t k = 1; k < n; ++k) {
      if ((byte(i + k) & 0xC0) != 0x80) return false;
    }
    if (b == 0xC2 && byte(i + 1) < 0xA0) return false;
    i += n;
  }
  return true;
}

// Every diagnostic printable and bounded; returns all of them joined, for finer checks.
std::string check_all(const std::vector<Diagnostic>& diagnostics) {
  std::string all;
  for (const Diagnostic& d : diagnostics) {
    const std::string line = d.to_string();
    EXPECT_TRUE(terminal_safe(line)) << line.substr(0, 200);
    EXPECT_LE(d.message.size(), kMaxMessageBytes) << d.message.substr(0, 200);
    EXPECT_LE(line.size(), d.file.size() + 40 + kMaxMessageBytes) << line.substr(0, 200);
    all += line + "\n";
  }
  return all;
}

const std::string kAnsi = "\x1b[2J\x1b[31mred\x07";           // clear screen, colour, bell
const std::string kC1 = "\xc2\x9b" "31m";                       // CSI as a C1 control (UTF-8)
const std::string kNotUtf8 = "\xff\xfe";
const std::string kHuge(3'000'000, 'A');                        // a 3 MB "line"

TEST(HostileMessages, DiagnosticToStringIsTerminalSafeAndBounded) {
  const Diagnostic d{Diagnostic::Severity::error, "f.vimg", 3, "bad " + kAnsi + kC1 + kNotUtf8 + kHuge};
  const std::string text = d.to_string();
  EXPECT_TRUE(terminal_safe(text));
  EXPECT_EQ(text.rfind("f.vimg:3: error: bad \\x1B[2J\\x1B[31mred\\x07\\xC2\\x9B31m\\xFF\\xFEAAA", 0), 0u) << text.substr(0, 120);
  EXPECT_LE(text.size(), std::string("f.vimg:3: error: ").size() + kMaxMessageBytes);
  EXPECT_EQ(text.substr(text.size() - 3), "...");
}

TEST(HostileMessages, EscapeInputKeepsUtf8AndCutsLongInput) {
  EXPECT_EQ(escape_input("caf\xc3\xa9 \xe2\x82\xac"), "caf\xc3\xa9 \xe2\x82\xac") << "valid UTF-8 text stays readable";
  EXPECT_EQ(escape_input(std::string("a\0b", 3)), "a\\x00b");
  EXPECT_EQ(escape_input("back\\slash"), "back\\\\slash");
  EXPECT_EQ(escape_input("\xe2\x80\xae" "evil"), "\\xE2\\x80\\xAEevil") << "a bidi override could reorder the line";
  EXPECT_EQ(escape_input("\xc3"), "\\xC3") << "a cut UTF-8 sequence is not UTF-8";
  const std::string cut = escape_input(kHuge);
  EXPECT_EQ(cut, std::string(kMaxQuotedInputBytes, 'A') + "...");
  const std::string cut_escapes = escape_input(std::string(1000, '\x1b'));
  EXPECT_LE(cut_escapes.size(), kMaxQuotedInputBytes + 3);
  EXPECT_EQ(cut_escapes.substr(0, 8), "\\x1B\\x1B");
}

TEST(HostileMessages, ImageMessagesQuoteInputSafely) {
  // XML allows C1 controls, DEL and bidi overrides, so they reach the value messages quoted.
  const std::string kDelAndBidi = "\x7F\xE2\x80\xAE" "evil";
  const std::string xml = "<vibroimage version=\"1.0\" width=\"10\" height=\"10\">\n"
                          "<dot x=\"" + kC1 + kDelAndBidi + kHuge + "\" y=\"1\" id=\"" + kC1 + "\"/>\n"
                          "<line x1=\"0\" y1=\"0\" x2=\"1\" y2=\"1\" " + std::string(5000, 'n') + "=\"" + kNotUtf8 + "\"/>\n"
                          "<surface shape=\"" + kC1 + "\"/>\n"
                          "</vibroimage>\n";
  const LoadResult r = parse_image_xml(xml, "hostile.vimg");
  ASSERT_FALSE(r.ok());
  const std::string all = check_all(r.diagnostics);
  EXPECT_NE(all.find("hostile.vimg:2: error: <dot> attribute 'x' = \"\\xC2\\x9B31m\\x7F\\xE2\\x80\\xAEevilAAA"), std::string::npos) << all;
  EXPECT_NE(all.find("hostile.vimg:4: error: <surface> attribute 'shape' = \"\\xC2\\x9B31m"), std::string::npos) << all;
}

TEST(HostileMessages, ImageWithTerminalEscapesIsRefusedWithoutEchoingThem) {
  // ESC and BEL are controls XML does not allow: the file is refused at the first one, named by
  // its byte value, before any value could be quoted.
  const std::string xml = "<vibroimage version=\"1.0\" width=\"10\" height=\"10\">\n"
                          "<dot x=\"1\" y=\"1\"/>\n<surface shape=\"" + kAnsi + kHuge + "\"/>\n</vibroimage>\n";
  const LoadResult r = parse_image_xml(xml, "escapes.vimg");
  ASSERT_FALSE(r.ok());
  check_all(r.diagnostics);
  ASSERT_EQ(r.diagnostics.size(), 1u);
  EXPECT_EQ(r.diagnostics[0].to_string(), "escapes.vimg:3: error: a control character (byte 0x1B) at offset " +
                                              std::to_string(xml.find('\x1b')) + ", which XML does not allow");
}

TEST(HostileMessages, ImageReportsTheFirstFiftyDiagnosticsAndCountsTheRest) {
  std::string xml = "<vibroimage version=\"1.0\" width=\"10\" height=\"10\">\n";
  for (int i = 0; i < 130; ++i) xml += "<dot x=\"nan\" y=\"1\"/>\n";          // lines 2..131: errors
  for (int i = 0; i < 20; ++i) xml += "<dot x=\"1\" y=\"1\" extra=\"1\"/>\n";  // lines 132..151: warnings
  xml += "</vibroimage>\n";
  const LoadResult r = parse_image_xml(xml, "many.vimg");
  ASSERT_FALSE(r.ok());
  ASSERT_EQ(r.diagnostics.size(), kMaxDiagnosticsPerFile + 1);
  for (std::size_t i = 0; i < kMaxDiagnosticsPerFile; ++i) EXPECT_EQ(r.diagnostics[i].line, static_cast<int>(i) + 2);
  EXPECT_EQ(r.diagnostics.back().to_string(),
            "many.vimg: error: 100 more diagnostics not shown: 80 errors, 20 warnings (limit 50 per file)");
}

TEST(HostileMessages, TwoPassesTogetherKeepTheBoundAndShowErrorsBeforeWarnings) {
  // An import's 57 warnings (50 kept, 7 counted), then a read-back with one error and 55
  // warnings (the error and 49 kept, 6 counted): 102 lines in all become 50 and one summary.
  DiagnosticList import("a.svg");
  for (int i = 0; i < 57; ++i) import.warning(i + 1, "import warning " + std::to_string(i));
  DiagnosticList back("a.svg");
  back.error(0, "too many attributes");
  for (int i = 0; i < 55; ++i) back.warning(0, "outside " + std::to_string(i));
  std::vector<Diagnostic> first = import.take(), second = back.take();
  ASSERT_EQ(first.size(), 51u);
  ASSERT_EQ(second.size(), 51u);
  const std::vector<Diagnostic> merged = merge_diagnostics(first, second, "a.svg");
  ASSERT_EQ(merged.size(), kMaxDiagnosticsPerFile + 1);
  check_all(merged);
  EXPECT_EQ(merged[0].message, "import warning 0");
  EXPECT_EQ(merged[48].message, "import warning 48");
  EXPECT_EQ(merged[49].message, "too many attributes") << "the error stays; the last warnings go";
  // 7 + 6 counted before, and now the 49 read-back warnings and the import's 50th.
  EXPECT_EQ(merged.back().to_string(), "a.svg: warning: 63 more diagnostics not shown: 63 warnings (limit 50 per file)");
  EXPECT_EQ(merge_diagnostics(first, {}, "a.svg").back().to_string(), first.back().to_string()) << "a list alone stays as it was";
}

TEST(HostileMessages, OnlyWarningsDroppedGiveAWarningSummary) {
  std::string xml = "<vibroimage version=\"1.0\" width=\"10\" height=\"10\">\n";
  for (int i = 0; i < 60; ++i) xml += "<dot x=\"1\" y=\"1\" extra=\"1\"/>\n";
  xml += "</vibroimage>\n";
  const LoadResult r = parse_image_xml(xml, "w.vimg");
  ASSERT_TRUE(r.ok()) << "warnings never stop loading, shown or not";
  ASSERT_EQ(r.diagnostics.size(), kMaxDiagnosticsPerFile + 1);
  EXPECT_EQ(r.diagnostics.back().to_string(), "w.vimg: warning: 10 more diagnostics not shown: 10 warnings (limit 50 per file)");
}

TEST(HostileMessages, NrrdHeaderMessagesQuoteInputSafely) {
  const std::string text = "NRRD0004\n" + kAnsi + kHuge.substr(0, 100000) + ": 3\ntype: " + kC1 + "\nno colon " + kNotUtf8 +
                           "\ndimension: 3\nsizes: 1 1 1\nencoding: raw\n\n\x01";
  const NrrdLoadResult r = parse_nrrd(text, "hostile.nrrd");
  ASSERT_FALSE(r.ok());
  const std::string all = check_all(r.diagnostics);
  EXPECT_NE(all.find("hostile.nrrd:4: error: expected 'field: value', got 'no colon \\xFF\\xFE'"), std::string::npos) << all;
}

TEST(HostileMessages, NrrdHeaderLongerThanItsLimitIsRefused) {
  const std::string text = "NRRD0004\n# " + std::string(kMaxNrrdHeaderBytes, 'c') + "\ntype: uchar\n\n";
  const NrrdLoadResult r = parse_nrrd(text, "long.nrrd");
  ASSERT_FALSE(r.ok());
  ASSERT_FALSE(r.diagnostics.empty());
  EXPECT_EQ(r.diagnostics[0].to_string(),
            "long.nrrd:2: error: the header is longer than 1048576 bytes (limit 1048576)");
}

TEST(HostileMessages, ProbePathMessagesQuoteInputSafelyAndAreCapped) {
  std::string csv = "time_s,x_mm,y_mm,z_mm\n0," + kAnsi + kHuge + ",0,0\n";
  for (int i = 0; i < 100; ++i) csv += std::to_string(i + 1) + ",0,0," + kC1 + "\n";
  const ProbePathParseResult r = parse_probe_path_csv(csv, "hostile.csv");
  ASSERT_FALSE(r.path.has_value());
  const std::string all = check_all(r.diagnostics);
  EXPECT_EQ(r.diagnostics.front().to_string().rfind("hostile.csv:2: error: column 2: '\\x1B[2J\\x1B[31mred\\x07AAA", 0), 0u) << all;
  ASSERT_EQ(r.diagnostics.size(), kMaxDiagnosticsPerFile + 1);
  EXPECT_EQ(r.diagnostics.back().to_string(), "hostile.csv: error: 51 more diagnostics not shown: 51 errors (limit 50 per file)");
}

TEST(HostileMessages, SceneMessagesQuoteInputSafely) {
  const std::string xml = "<volumeScene version=\"1.0\">\n<scalarData id=\"s\" file=\"s.nrrd\" " + std::string(3000, 'q') +
                          "=\"1\"/>\n<device name=\"d\" rate=\"" + kC1 + kNotUtf8 + "\"/>\n<x" + kC1 + "/>\n</volumeScene>\n";
  const VolumeSceneParseResult r = parse_volume_scene_xml(xml, "hostile.xml");
  ASSERT_FALSE(r.ok());
  const std::string all = check_all(r.diagnostics);
  EXPECT_NE(all.find("hostile.xml:3: error: attribute 'rate': '\\xC2\\x9B31m\\xFF\\xFE'"), std::string::npos) << all;
  EXPECT_NE(all.find("hostile.xml:4: error: unknown element <x\\xC2\\x9B31m>"), std::string::npos) << all;
}

}  // namespace
}  // namespace vimg
