#include "editor/core/document_session.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "storage/image_io.hpp"
#include "storage/png_codec.hpp"

namespace vimg::editor {
namespace {

struct SessionDirs {
  std::filesystem::path root;
  explicit SessionDirs(const std::string& name) : root(std::filesystem::path(VIMG_BINARY_DIR) / name) {
    std::filesystem::remove_all(root);
    std::filesystem::create_directories(root);
  }
  ~SessionDirs() { std::filesystem::remove_all(root); }
  DocumentSession::Options options(double autosave_s = 5.0) const {
    return {root / "recent.txt", root / "recovery", autosave_s, "9.9.9"};
  }
};

Element dot_at(double x, double y) {
  Element e;
  e.body = Dot{x, y, 2.0, 1.0};
  return e;
}

TEST(DocumentSession, StartsWithABlankUntitledPage) {
  SessionDirs dirs("editor_test_session_blank");
  DocumentSession session(dirs.options());
  EXPECT_EQ(session.path(), "");
  EXPECT_EQ(session.display_name(), "untitled");
  EXPECT_FALSE(session.editor().dirty());
  EXPECT_EQ(session.editor().image().width_mm, 100.0);
  ASSERT_TRUE(session.editor().image().meta && session.editor().image().meta->tool);
  EXPECT_EQ(session.editor().image().meta->tool->version, "9.9.9");
}

TEST(DocumentSession, SaveOpenRoundTripUpdatesPathRecentFilesAndDirtyState) {
  SessionDirs dirs("editor_test_session_roundtrip");
  DocumentSession session(dirs.options());
  session.editor().add_element(dot_at(10, 20));
  EXPECT_TRUE(session.editor().dirty());
  const std::string file = (dirs.root / "a.vimg").string();
  ASSERT_EQ(session.save_to(file, true), std::nullopt);
  EXPECT_FALSE(session.editor().dirty());
  EXPECT_EQ(session.path(), file);
  EXPECT_EQ(session.display_name(), "a.vimg");
  ASSERT_FALSE(session.recent().paths().empty());
  EXPECT_EQ(session.recent().paths().front(), file);

  // A copy (export) leaves the document's own path alone.
  const std::string copy = (dirs.root / "copy.vimg").string();
  session.editor().add_element(dot_at(30, 30));
  ASSERT_EQ(session.save_to(copy, false), std::nullopt);
  EXPECT_EQ(session.path(), file);
  EXPECT_TRUE(session.editor().dirty());

  DocumentSession other(dirs.options());
  bool replaced = false;
  ASSERT_EQ(other.open(file, [&] { replaced = true; }), std::nullopt);
  EXPECT_TRUE(replaced);
  EXPECT_EQ(other.path(), file);
  EXPECT_FALSE(other.editor().dirty());
  ASSERT_EQ(other.editor().image().children.size(), 1u);
  EXPECT_TRUE(other.load_diagnostics().empty());
}

TEST(DocumentSession, AFileThatCannotBeReadLeavesTheDocumentAndLeavesRecentFiles) {
  SessionDirs dirs("editor_test_session_bad");
  DocumentSession session(dirs.options());
  const std::string good = (dirs.root / "good.vimg").string();
  session.editor().add_element(dot_at(10, 20));
  ASSERT_EQ(session.save_to(good, true), std::nullopt);
  std::ofstream(good) << "<not-a-vibroimage/>";
  bool replaced = false;
  const auto error = session.open(good, [&] { replaced = true; });
  ASSERT_TRUE(error.has_value());
  EXPECT_NE(error->find("good.vimg"), std::string::npos) << *error;
  EXPECT_FALSE(replaced);
  EXPECT_EQ(session.editor().image().children.size(), 1u);
  EXPECT_TRUE(session.recent().paths().empty());
}

TEST(DocumentSession, AutosavesOnlyADirtyChangedDocumentAfterTheInterval) {
  SessionDirs dirs("editor_test_session_autosave");
  DocumentSession session(dirs.options(5.0));
  EXPECT_EQ(session.autosave_if_due(100.0), std::nullopt);  // not dirty
  session.editor().add_element(dot_at(10, 20));
  EXPECT_EQ(session.autosave_if_due(100.0), std::optional<std::string>("autosaved"));
  EXPECT_EQ(session.autosave_if_due(200.0), std::nullopt);  // nothing changed since
  session.editor().add_element(dot_at(20, 20));
  EXPECT_EQ(session.autosave_if_due(104.0), std::nullopt);  // within the interval
  session.editor().begin_gesture();
  EXPECT_EQ(session.autosave_if_due(106.0), std::nullopt);  // mid-drag
  session.editor().end_gesture();
  EXPECT_EQ(session.autosave_if_due(106.0), std::optional<std::string>("autosaved"));
}

TEST(DocumentSession, ACrashedSessionsWorkIsOfferedAndRecoveredAsUnsaved) {
  SessionDirs dirs("editor_test_session_recover");
  const std::string origin = (dirs.root / "work.vimg").string();
  {
    DocumentSession crashed(dirs.options(0.0));
    crashed.editor().add_element(dot_at(60, 20));
    ASSERT_EQ(crashed.save_to(origin, true), std::nullopt);
    crashed.editor().add_element(dot_at(70, 20));
    ASSERT_EQ(crashed.autosave_if_due(1.0), std::optional<std::string>("autosaved"));
  }  // ends without end_session(): the slot stays, unlocked
  DocumentSession next(dirs.options(0.0));
  ASSERT_TRUE(next.offer_recovery());
  EXPECT_TRUE(next.recovery_pending());
  EXPECT_EQ(next.recovery_origin(), origin);
  // While the designer decides, a new document does not remove the slot and nothing autosaves.
  next.new_document();
  next.editor().add_element(dot_at(1, 1));
  EXPECT_EQ(next.autosave_if_due(10.0), std::nullopt);
  ASSERT_EQ(next.recover(), std::nullopt);
  EXPECT_FALSE(next.recovery_pending());
  EXPECT_EQ(next.path(), origin);
  EXPECT_TRUE(next.editor().dirty());
  EXPECT_EQ(next.editor().image().children.size(), 2u);
  next.end_session();
  DocumentSession after(dirs.options(0.0));
  EXPECT_FALSE(after.offer_recovery());
}

TEST(DocumentSession, DiscardingTheOfferedWorkRemovesIt) {
  SessionDirs dirs("editor_test_session_discard");
  {
    DocumentSession crashed(dirs.options(0.0));
    crashed.editor().add_element(dot_at(60, 20));
    ASSERT_EQ(crashed.autosave_if_due(1.0), std::optional<std::string>("autosaved"));
  }
  {
    DocumentSession next(dirs.options(0.0));
    ASSERT_TRUE(next.offer_recovery());
    next.discard_recovery();
    EXPECT_FALSE(next.recovery_pending());
  }
  DocumentSession after(dirs.options(0.0));
  EXPECT_FALSE(after.offer_recovery());
}

// File -> Import

void write_text(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

// A PNG picture of width x height pixels at `pixels_per_metre`, without the vibroimage chunk.
std::string plain_png(int width, int height, std::uint32_t pixels_per_metre) {
  RgbRaster raster;
  raster.width = width;
  raster.height = height;
  raster.rgb.assign(static_cast<std::size_t>(width * height * 3), 255);
  for (int x = 0; x < width / 2; ++x) {
    for (int y = 0; y < height; ++y) std::fill_n(raster.pixel(x, y), 3, std::uint8_t{0});  // left half black
  }
  const std::string png = encode_png(raster, pixels_per_metre, "<x/>").bytes;
  std::string out = png.substr(0, 8);
  for (std::size_t at = 8; at + 12 <= png.size();) {
    const std::size_t length = (std::size_t{static_cast<unsigned char>(png[at])} << 24) |
                               (std::size_t{static_cast<unsigned char>(png[at + 1])} << 16) |
                               (std::size_t{static_cast<unsigned char>(png[at + 2])} << 8) |
                               static_cast<unsigned char>(png[at + 3]);
    if (png.compare(at + 4, 4, "iTXt") != 0) out += png.substr(at, length + 12);
    at += length + 12;
  }
  return out;
}

constexpr const char* kSvg = R"(<svg xmlns="http://www.w3.org/2000/svg" width="80mm" height="60mm" viewBox="0 0 80 60">
  <rect id="panel" x="5" y="5" width="25" height="15" fill="#444"/>
  <line id="rail" x1="5" y1="30" x2="75" y2="30" stroke="black" stroke-width="1.5"/>
  <text x="40" y="58">not imported</text>
</svg>)";

TEST(DocumentSessionImport, ADrawingBecomesAnUntitledUnsavedDocumentWithItsWarnings) {
  SessionDirs dirs("editor_test_session_import_svg");
  DocumentSession session(dirs.options());
  const std::string opened = (dirs.root / "a.vimg").string();
  ASSERT_EQ(session.save_to(opened, true), std::nullopt);
  const std::filesystem::path svg = dirs.root / "drawing.svg";
  write_text(svg, kSvg);
  int replaced = 0;
  ASSERT_EQ(session.import_into_new_document(svg.string(), {}, [&] { ++replaced; }), std::nullopt);
  EXPECT_EQ(replaced, 1);
  EXPECT_EQ(session.path(), "");  // a new document: Save asks where
  EXPECT_TRUE(session.editor().dirty());
  EXPECT_DOUBLE_EQ(session.editor().image().width_mm, 80.0);
  EXPECT_DOUBLE_EQ(session.editor().image().height_mm, 60.0);
  EXPECT_EQ(session.editor().image().children.size(), 2u);  // the rect and the line; not the text
  ASSERT_FALSE(session.load_diagnostics().empty());
  for (const Diagnostic& d : session.load_diagnostics()) EXPECT_EQ(d.severity, Diagnostic::Severity::warning) << d.to_string();
  EXPECT_EQ(session.recent().paths().front(), opened);  // the SVG is not a recent document

  // mm per unit overrides the size of the file.
  ImportOptions scaled;
  scaled.mm_per_unit = 2.0;
  ASSERT_EQ(session.import_into_new_document(svg.string(), scaled), std::nullopt);
  EXPECT_DOUBLE_EQ(session.editor().image().width_mm, 160.0);
}

TEST(DocumentSessionImport, AFailedImportLeavesTheDocumentAlone) {
  SessionDirs dirs("editor_test_session_import_bad");
  DocumentSession session(dirs.options());
  const std::string opened = (dirs.root / "a.vimg").string();
  session.editor().add_element(dot_at(10, 20));
  ASSERT_EQ(session.save_to(opened, true), std::nullopt);
  const std::filesystem::path bad = dirs.root / "bad.svg";
  write_text(bad, "<svg xmlns=\"http://www.w3.org/2000/svg\"><rect width=\"3\"");
  bool replaced = false;
  for (const std::filesystem::path& p : {bad, dirs.root / "missing.svg", dirs.root / "a.vimg"}) {
    const auto error = session.import_into_new_document(p.string(), {}, [&] { replaced = true; });
    ASSERT_TRUE(error.has_value()) << p;
    EXPECT_NE(error->find(p.string() + ":"), std::string::npos) << *error;
    EXPECT_NE(error->find("error"), std::string::npos) << *error;
  }
  // A picture needs a width.
  write_text(dirs.root / "pic.png", plain_png(8, 4, 0));
  EXPECT_TRUE(session.import_into_new_document((dirs.root / "pic.png").string(), {}).has_value());
  EXPECT_FALSE(replaced);
  EXPECT_EQ(session.path(), opened);
  EXPECT_EQ(session.editor().image().children.size(), 1u);
  EXPECT_FALSE(session.editor().dirty());
}

TEST(DocumentSessionImport, APictureImportsAtTheGivenWidthAndAVibroimagePngIsOpened) {
  SessionDirs dirs("editor_test_session_import_png");
  DocumentSession session(dirs.options());
  const std::filesystem::path pic = dirs.root / "pic.png";
  write_text(pic, plain_png(40, 20, 0));
  ImportOptions options;
  options.width_mm = 60.0;
  options.levels = 2;
  ASSERT_EQ(session.import_into_new_document(pic.string(), options), std::nullopt);
  EXPECT_EQ(session.path(), "");
  EXPECT_DOUBLE_EQ(session.editor().image().width_mm, 60.0);
  EXPECT_DOUBLE_EQ(session.editor().image().height_mm, 30.0);  // the picture's aspect ratio
  EXPECT_FALSE(session.editor().image().children.empty());
  EXPECT_FALSE(import_question(pic.string()).vibroimage);

  // Saved as a PNG vibroimage, the same file is opened, not imported as a picture.
  const std::string saved = (dirs.root / "saved.png").string();
  ASSERT_EQ(session.save_to(saved, false), std::nullopt);
  const std::size_t children = session.editor().image().children.size();
  EXPECT_TRUE(import_question(saved).vibroimage);
  ASSERT_EQ(session.import_into_new_document(saved, {}), std::nullopt);
  EXPECT_EQ(session.path(), saved);
  EXPECT_FALSE(session.editor().dirty());
  EXPECT_EQ(session.editor().image().children.size(), children);
}

TEST(DocumentSessionImport, ThePictureWidthComesFromPhysOrDefaultsTo100Mm) {
  for (const auto& [width_px, per_metre] : {std::pair{40, 1000u}, {300, 11811u}, {7, 96u}, {1, 3u}}) {
    const std::string png = plain_png(width_px, 3, per_metre);
    const auto width_mm = png_physical_width_mm(png);
    ASSERT_TRUE(width_mm.has_value()) << width_px << " px at " << per_metre << " px/m";
    EXPECT_NEAR(*width_mm, 1000.0 * width_px / per_metre, 1e-9);
  }
  EXPECT_EQ(png_physical_width_mm(plain_png(40, 3, 0)), std::nullopt);  // no meaningful pHYs
  std::string unknown_unit = plain_png(40, 3, 1000);  // pHYs giving only the aspect ratio
  const std::size_t phys = unknown_unit.find("pHYs");
  ASSERT_NE(phys, std::string::npos);
  unknown_unit[phys + 4 + 8] = 0;
  EXPECT_EQ(png_physical_width_mm(unknown_unit), std::nullopt);
  // Cut anywhere, the bytes give a width or nothing, never a read past the end.
  const std::string png = plain_png(40, 3, 2000);
  for (std::size_t n = 0; n < png.size(); ++n) {
    const auto width_mm = png_physical_width_mm(std::string_view(png).substr(0, n));
    if (width_mm) {
      EXPECT_DOUBLE_EQ(*width_mm, 20.0);
    }
  }
  SessionDirs dirs("editor_test_session_import_question");
  write_text(dirs.root / "a.png", plain_png(50, 3, 0));
  const ImportQuestion q = import_question((dirs.root / "a.png").string());
  EXPECT_TRUE(q.picture);
  EXPECT_FALSE(q.vibroimage);
  EXPECT_DOUBLE_EQ(q.width_mm, 100.0);
  EXPECT_FALSE(import_question((dirs.root / "a.svg").string()).picture);
}

}  // namespace
}  // namespace vimg::editor
