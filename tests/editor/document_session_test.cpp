#include "editor/core/document_session.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "storage/image_io.hpp"

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

}  // namespace
}  // namespace vimg::editor
