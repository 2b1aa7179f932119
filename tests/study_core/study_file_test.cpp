// Study files (storage/study/study_file.hpp, docs/format-studies.md "Matching study file" and "Location
// study file"): good files give the study, every problem is `FILE:LINE: error: ...` at its line.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <string>

#include "storage/limits.hpp"
#include "storage/study/study_file.hpp"
#include "tests/storage/storage_test_support.hpp"

namespace vimg {
namespace {

namespace fs = std::filesystem;

template <class T>
std::string messages(const StudyFileResult<T>& r) {
  std::string all;
  for (const auto& d : r.diagnostics) all += d.to_string() + "\n";
  return all;
}

// A study folder with images a.vimg, b.vimg, c.vimg and sub/a.vimg (the readers only check that
// each is a regular file inside the folder; what it holds is the runner's business).
class MatchingStudyFile : public ::testing::Test {
 protected:
  void SetUp() override {
    fs::create_directories(dir_ / "sub");
    for (const char* name : {"a.vimg", "b.vimg", "c.vimg", "sub/a.vimg"}) test::write_text_file(dir_ / name, "<vibroimage/>");
  }
  StudyFileResult<MatchingStudy> load(const std::string& text, bool allow_outside = false) {
    test::write_text_file(dir_ / "study.xml", text);
    return load_matching_study(dir_ / "study.xml", allow_outside);
  }
  std::string file() const { return (dir_ / "study.xml").string(); }
  // The one diagnostic a file gives.
  std::string only(const std::string& text) {
    const auto r = load(text);
    EXPECT_FALSE(r.ok());
    return r.diagnostics.size() == 1 ? r.diagnostics[0].to_string() : "several:\n" + messages(r);
  }

  test::TempDir dir_{"study_file"};
};

const std::string kTwoSets =
    "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
    "<matchingStudy version=\"1\" seed=\"2024\" repetitions=\"3\" trainingMinutes=\"2.5\">\n"
    "  <maskingNoise device=\"USB Audio\" level=\"0.35\"/>\n"
    "  <set name=\"complexity\">\n"
    "    <image file=\"a.vimg\"/> <image file=\"b.vimg\"/>\n"
    "    <image file=\"./c.vimg\"/>\n"
    "  </set>\n"
    "  <!-- a comment -->\n"
    "  <set name=\"same complexity\"><image file=\"sub/a.vimg\"/><image file=\"b.vimg\"/></set>\n"
    "</matchingStudy>\n";

TEST_F(MatchingStudyFile, ReadsEveryField) {
  const auto r = load(kTwoSets);
  ASSERT_TRUE(r.ok()) << messages(r);
  EXPECT_TRUE(r.diagnostics.empty()) << messages(r);
  const MatchingStudy& s = *r.study;
  EXPECT_EQ(s.seed, 2024u);
  EXPECT_EQ(s.repetitions, 3);
  EXPECT_EQ(s.training_minutes, 2.5);
  ASSERT_TRUE(s.masking_noise.has_value());
  EXPECT_EQ(s.masking_noise->audio_device, "USB Audio");
  EXPECT_EQ(s.masking_noise->level, 0.35);
  ASSERT_EQ(s.sets.size(), 2u);
  EXPECT_EQ(s.sets[0].name, "complexity");
  EXPECT_EQ(s.sets[0].images, (std::vector<fs::path>{dir_ / "a.vimg", dir_ / "b.vimg", dir_ / "c.vimg"}));
  EXPECT_EQ(s.sets[1].name, "same complexity");
  EXPECT_EQ(s.sets[1].images, (std::vector<fs::path>{dir_ / "sub/a.vimg", dir_ / "b.vimg"}));
  EXPECT_EQ(study_image_name(s.sets[1].images[0]), "a");
}

TEST_F(MatchingStudyFile, DefaultsWhereTheFileIsSilent) {
  const auto r = load("<matchingStudy version=\"1\"><set name=\"s\"><image file=\"a.vimg\"/><image file=\"b.vimg\"/></set></matchingStudy>");
  ASSERT_TRUE(r.ok()) << messages(r);
  EXPECT_EQ(r.study->seed, 1u);
  EXPECT_EQ(r.study->repetitions, 5);
  EXPECT_EQ(r.study->training_minutes, 3.0);
  EXPECT_FALSE(r.study->masking_noise.has_value());
}

TEST_F(MatchingStudyFile, EachProblemAtItsLine) {
  const std::string f = file();
  const std::string set = "<set name=\"s\"><image file=\"a.vimg\"/><image file=\"b.vimg\"/></set>";
  EXPECT_EQ(only("<matchingStudy version=\"1\">\n</matchingStudy>"),
            f + ":1: error: <matchingStudy> needs at least one <set> of images");
  EXPECT_EQ(only("<matchingStudy version=\"1\">\n<set name=\"s\">\n<image file=\"a.vimg\"/>\n</set></matchingStudy>"),
            f + ":2: error: <set> needs at least two <image> elements (a participant chooses among them), found 1");
  EXPECT_EQ(only("<matchingStudy version=\"1\"><set name=\"s\">\n<image file=\"a.vimg\"/>\n<image file=\"sub/a.vimg\"/></set></matchingStudy>"),
            f + ":3: error: <image> 'sub/a.vimg' has the name 'a' of the image on line 2 (trial files name images by their file's stem)");
  EXPECT_EQ(only("<matchingStudy version=\"1\" repetitions=\"0\">" + set + "</matchingStudy>"),
            f + ":1: error: attribute 'repetitions' must be a whole number in 1..100, got '0'");
  EXPECT_EQ(only("<matchingStudy version=\"1\" repetitions=\"2.5\">" + set + "</matchingStudy>"),
            f + ":1: error: attribute 'repetitions' must be a whole number in 1..100, got '2.5'");
  EXPECT_EQ(only("<matchingStudy version=\"1\" trainingMinutes=\"-1\">" + set + "</matchingStudy>"),
            f + ":1: error: attribute 'trainingMinutes' must be in [0, 600], got -1");
  EXPECT_EQ(only("<matchingStudy version=\"1\" seed=\"-3\">" + set + "</matchingStudy>"),
            f + ":1: error: attribute 'seed' must be a whole number in 0..18446744073709551615, got '-3'");
  EXPECT_EQ(only("<matchingStudy version=\"1\">\n<maskingNoise device=\"x\" level=\"1.5\"/>" + set + "</matchingStudy>"),
            f + ":2: error: attribute 'level' must be in [0, 1], got 1.5");
  EXPECT_EQ(only("<matchingStudy version=\"1\">\n<maskingNoise level=\"0.5\"/>" + set + "</matchingStudy>"),
            f + ":2: error: <maskingNoise> needs attribute 'device'");
  EXPECT_EQ(only("<matchingStudy version=\"1\"><maskingNoise device=\"x\"/>\n<maskingNoise device=\"y\"/>" + set + "</matchingStudy>"),
            f + ":2: error: second <maskingNoise> (first on line 1)");
  EXPECT_EQ(only("<matchingStudy version=\"1\">" + set + "\n<set name=\"s\"><image file=\"a.vimg\"/><image file=\"c.vimg\"/></set></matchingStudy>"),
            f + ":2: error: second set named 's' (first on line 1)");
  EXPECT_EQ(only("<matchingStudy version=\"1\"><set name=\"a,b\"><image file=\"a.vimg\"/><image file=\"b.vimg\"/></set></matchingStudy>"),
            f + ":1: error: attribute 'name' = 'a,b' holds a comma (it names a cell of the trial file)");
  EXPECT_EQ(only("<matchingStudy version=\"2\">" + set + "</matchingStudy>"),
            f + ":1: error: <matchingStudy> version '2' is not supported (this program reads version 1)");
  EXPECT_EQ(only("<matchingStudy>" + set + "</matchingStudy>"), f + ":1: error: <matchingStudy> needs attribute 'version' (\"1\")");
}

TEST_F(MatchingStudyFile, InstructionsAndConsentAreTextInParagraphs) {
  const std::string set = "<set name=\"s\"><image file=\"a.vimg\"/><image file=\"b.vimg\"/></set>";
  auto r = load("<matchingStudy version=\"1\">\n  <instructions>\n    Rub the screen,\n    then press Answer.\n\n"
                "    Take  your time &amp; breathe.\n  </instructions>\n  <consent>I agree.</consent>" + set + "</matchingStudy>");
  ASSERT_TRUE(r.ok()) << messages(r);
  EXPECT_EQ(r.study->instructions, "Rub the screen, then press Answer.\n\nTake  your time & breathe.");
  EXPECT_EQ(r.study->consent, "I agree.");
  r = load("<matchingStudy version=\"1\">" + set + "</matchingStudy>");
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r.study->instructions, "");
  EXPECT_EQ(r.study->consent, "");
  const std::string f = file();
  EXPECT_EQ(only("<matchingStudy version=\"1\"><consent>a</consent>\n<consent>b</consent>" + set + "</matchingStudy>"),
            f + ":2: error: second <consent> (first on line 1)");
  EXPECT_EQ(only("<matchingStudy version=\"1\"><instructions>a\n<b>bold</b></instructions>" + set + "</matchingStudy>"),
            f + ":2: error: <instructions> holds text only, found <b>");
  EXPECT_EQ(only("<matchingStudy version=\"1\"><consent lang=\"en\">a</consent>" + set + "</matchingStudy>"),
            f + ":1: error: unknown attribute 'lang' on <consent>");
  EXPECT_EQ(only("<matchingStudy version=\"1\"><consent>" + std::string(kMaxStudyTextBytes + 1, 'x') + "</consent>" + set +
                 "</matchingStudy>"),
            f + ":1: error: <consent> holds 16385 bytes, more than 16384 (limit 16384)");
}

TEST_F(MatchingStudyFile, UnknownElementsAndAttributesAreNamed) {
  const std::string f = file();
  EXPECT_EQ(only("<matchingStudy version=\"1\" colour=\"red\"><set name=\"s\"><image file=\"a.vimg\"/><image file=\"b.vimg\"/></set></matchingStudy>"),
            f + ":1: error: unknown attribute 'colour' on <matchingStudy>");
  EXPECT_EQ(only("<matchingStudy version=\"1\">\n<pause/><set name=\"s\"><image file=\"a.vimg\"/><image file=\"b.vimg\"/></set></matchingStudy>"),
            f + ":2: error: unknown element <pause> in <matchingStudy>");
  EXPECT_EQ(only("<matchingStudy version=\"1\"><set name=\"s\"><image file=\"a.vimg\"/>\n<picture/><image file=\"b.vimg\"/></set></matchingStudy>"),
            f + ":2: error: unknown element <picture> in <set>");
  EXPECT_EQ(only("<matchingStudy version=\"1\"><set name=\"s\"><image file=\"a.vimg\" gain=\"1\"/><image file=\"b.vimg\"/></set></matchingStudy>"),
            f + ":1: error: unknown attribute 'gain' on <image>");
  EXPECT_EQ(only("<matchingStudy version=\"1\"><set name=\"s\">dot<image file=\"a.vimg\"/><image file=\"b.vimg\"/></set></matchingStudy>"),
            f + ":1: error: text is not allowed in <set>: 'dot'");
  EXPECT_EQ(only("<locationStudy version=\"1\"/>"), f + ":1: error: the root element must be <matchingStudy>, found <locationStudy>");
}

TEST_F(MatchingStudyFile, MalformedXmlIsReportedAsEveryReaderDoes) {
  const std::string f = file();
  EXPECT_EQ(only("<matchingStudy version=\"1\">\n<set name=\"s\">\n</matchingStudy>"),
            f + ":3: error: </matchingStudy> does not close <set> (opened at line 2)");
  EXPECT_EQ(only("<!DOCTYPE x [<!ENTITY a \"b\">]>\n<matchingStudy version=\"1\"/>").substr(0, f.size() + 10), f + ":1: error:");
}

TEST_F(MatchingStudyFile, ImagePathsAreConfinedToTheStudysFolder) {
  const std::string f = file();
  test::write_text_file(dir_.path().parent_path() / ("outside_" + dir_.path().filename().string() + ".vimg"), "x");
  const std::string outside = "../outside_" + dir_.path().filename().string() + ".vimg";
  const std::string text = "<matchingStudy version=\"1\"><set name=\"s\"><image file=\"a.vimg\"/>\n<image file=\"" + outside +
                           "\"/></set></matchingStudy>";
  EXPECT_EQ(only(text), f + ":2: error: <image> attribute 'file' = \"" + outside +
                            "\": leads outside the study's folder (data files must be in it or below it unless loading is allowed to leave it)");
  const auto allowed = load(text, true);
  EXPECT_TRUE(allowed.ok()) << messages(allowed);
  fs::remove(dir_.path().parent_path() / ("outside_" + dir_.path().filename().string() + ".vimg"));

  EXPECT_EQ(only("<matchingStudy version=\"1\"><set name=\"s\"><image file=\"a.vimg\"/>\n<image file=\"missing.vimg\"/></set></matchingStudy>"),
            f + ":2: error: <image> attribute 'file' = \"missing.vimg\": cannot open: No such file or directory");
  fs::create_symlink("a.vimg", dir_ / "link.vimg");
  EXPECT_EQ(only("<matchingStudy version=\"1\"><set name=\"s\"><image file=\"a.vimg\"/>\n<image file=\"link.vimg\"/></set></matchingStudy>"),
            f + ":2: error: <image> attribute 'file' = \"link.vimg\": is a symbolic link (name the file itself)");
  ASSERT_EQ(::mkfifo((dir_ / "fifo.vimg").c_str(), 0600), 0);
  EXPECT_EQ(only("<matchingStudy version=\"1\"><set name=\"s\"><image file=\"a.vimg\"/>\n<image file=\"fifo.vimg\"/></set></matchingStudy>"),
            f + ":2: error: <image> attribute 'file' = \"fifo.vimg\": is not a regular file (a FIFO)");
}

TEST_F(MatchingStudyFile, Limits) {
  const std::string f = file();
  std::string images;
  for (std::size_t i = 0; i <= kMaxStudyImagesPerSet; ++i) {
    test::write_text_file(dir_ / ("i" + std::to_string(i) + ".vimg"), "x");
    images += "<image file=\"i" + std::to_string(i) + ".vimg\"/>\n";
  }
  EXPECT_EQ(only("<matchingStudy version=\"1\"><set name=\"s\">\n" + images + "</set></matchingStudy>"),
            f + ":66: error: more than 64 images in one set (limit 64)");
  std::string sets;
  for (std::size_t i = 0; i <= kMaxStudySets; ++i) {
    sets += "<set name=\"s" + std::to_string(i) + "\"><image file=\"a.vimg\"/><image file=\"b.vimg\"/></set>\n";
  }
  EXPECT_EQ(only("<matchingStudy version=\"1\">\n" + sets + "</matchingStudy>"), f + ":66: error: more than 64 sets (limit 64)");
  // 64 sets of 2 images, 100 repetitions: 12 800 trials.
  sets.clear();
  for (std::size_t i = 0; i < kMaxStudySets; ++i) {
    sets += "<set name=\"s" + std::to_string(i) + "\"><image file=\"a.vimg\"/><image file=\"b.vimg\"/></set>\n";
  }
  EXPECT_EQ(only("<matchingStudy version=\"1\" repetitions=\"100\">\n" + sets + "</matchingStudy>"),
            f + ":1: error: the study has 12800 trials (images x repetitions), more than 10000 (limit 10000)");
  EXPECT_EQ(only(std::string(kMaxStudyFileBytes + 1, ' ')),
            f + ": error: is larger than 1 MiB (limit 1048576 bytes)");
}

// --- Location study files ------------------------------------------------------------------------

StudyFileResult<LocationStudy> location(const std::string& text) { return parse_location_study(text, "l.xml"); }

std::string location_only(const std::string& text) {
  const auto r = location(text);
  EXPECT_FALSE(r.ok());
  return r.diagnostics.size() == 1 ? r.diagnostics[0].to_string() : "several:\n" + messages(r);
}

TEST(LocationStudyFile, ReadsEveryField) {
  const auto r = location("<locationStudy version=\"1\" seed=\"7\" trialsPerMetaphor=\"4\" order=\"interleaved\">\n"
                          "  <metaphor name=\"transitionCue\"/>\n  <metaphor name=\"roughness\"/>\n</locationStudy>\n");
  ASSERT_TRUE(r.ok()) << messages(r);
  EXPECT_EQ(r.study->seed, 7u);
  EXPECT_EQ(r.study->trials_per_metaphor, 4);
  EXPECT_EQ(r.study->order, TrialOrder::interleaved);
  EXPECT_EQ(r.study->metaphors, (std::vector{LocationMetaphor::transition_cue, LocationMetaphor::roughness}));
}

TEST(LocationStudyFile, DefaultsArePapersDesign) {
  const auto r = location("<locationStudy version=\"1\"/>");
  ASSERT_TRUE(r.ok()) << messages(r);
  EXPECT_EQ(r.study->seed, 1u);
  EXPECT_EQ(r.study->trials_per_metaphor, 7);
  EXPECT_EQ(r.study->order, TrialOrder::blocked);
  EXPECT_EQ(r.study->metaphors, (std::vector{LocationMetaphor::roughness, LocationMetaphor::transition_cue}));
  const auto one = location("<locationStudy version=\"1\"><metaphor name=\"roughness\"/></locationStudy>");
  ASSERT_TRUE(one.ok());
  EXPECT_EQ(one.study->metaphors, std::vector{LocationMetaphor::roughness});
}

TEST(LocationStudyFile, EachProblemAtItsLine) {
  EXPECT_EQ(location_only("<locationStudy version=\"1\">\n<metaphor name=\"roughness\"/>\n<metaphor name=\"roughness\"/></locationStudy>"),
            "l.xml:3: error: metaphor roughness named twice (first on line 2)");
  EXPECT_EQ(location_only("<locationStudy version=\"1\">\n<metaphor name=\"friction\"/></locationStudy>"),
            "l.xml:2: error: <metaphor> name must be roughness or transitionCue, got 'friction'");
  EXPECT_EQ(location_only("<locationStudy version=\"1\">\n<metaphor/></locationStudy>"), "l.xml:2: error: <metaphor> needs attribute 'name'");
  EXPECT_EQ(location_only("<locationStudy version=\"1\" order=\"random\"/>"),
            "l.xml:1: error: attribute 'order' must be blocked or interleaved, got 'random'");
  EXPECT_EQ(location_only("<locationStudy version=\"1\" trialsPerMetaphor=\"0\"/>"),
            "l.xml:1: error: attribute 'trialsPerMetaphor' must be a whole number in 1..10000, got '0'");
  EXPECT_EQ(location_only("<locationStudy version=\"1\" trialsPerMetaphor=\"5001\"/>"),
            "l.xml:1: error: the study has 10002 trials (metaphors x trialsPerMetaphor), more than 10000 (limit 10000)");
  EXPECT_EQ(location_only("<locationStudy version=\"1\">\n<dataSet bend=\"3\"/></locationStudy>"),
            "l.xml:2: error: unknown element <dataSet> in <locationStudy>");
  EXPECT_EQ(location_only("<locationStudy version=\"1\" trials=\"3\"/>"), "l.xml:1: error: unknown attribute 'trials' on <locationStudy>");
  EXPECT_EQ(location_only("<locationStudy version=\"1\"><metaphor name=\"roughness\"><x/></metaphor></locationStudy>"),
            "l.xml:1: error: <metaphor> takes no children, found <x>");
  EXPECT_EQ(location_only("<matchingStudy version=\"1\"/>"), "l.xml:1: error: the root element must be <locationStudy>, found <matchingStudy>");
  EXPECT_EQ(location_only(""), "l.xml: error: not well-formed XML: no element at all (the file is empty or only blanks) (XML_ERROR_EMPTY_DOCUMENT)");
}

TEST(LocationStudyFile, MissingFileIsNamed) {
  const auto r = load_location_study("/nonexistent/l.xml");
  ASSERT_EQ(r.diagnostics.size(), 1u);
  EXPECT_EQ(r.diagnostics[0].to_string(), "/nonexistent/l.xml: error: cannot open: No such file or directory");
}

}  // namespace
}  // namespace vimg
