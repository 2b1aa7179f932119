// Atomic save (spec section 4): a process killed mid-save leaves the old file or the complete new
// one, never a torn file.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <string>
#include <thread>

#include "storage/atomic_file.hpp"
#include "storage/image_io.hpp"
#include "storage/limits.hpp"
#include "storage_test_support.hpp"

namespace vimg {
namespace {

Image many_dots(int count, double gain) {
  Image image;
  image.width_mm = 1000;
  image.height_mm = 1000;
  for (int i = 0; i < count; ++i) {
    Element e;
    e.id = "d" + std::to_string(i);
    e.body = Dot{static_cast<double>(i % 997) + 0.123456789, static_cast<double>(i % 991) + 0.987654321, 1.25, gain};
    image.children.push_back(std::move(e));
  }
  return image;
}

// The temporaries a killed saver left next to `target` (".work.vimg.tmp-PID-N"); removes them.
int take_leftover_temporaries(const std::filesystem::path& target) {
  const std::string prefix = "." + target.filename().string() + ".tmp-";
  int found = 0;
  for (const auto& entry : std::filesystem::directory_iterator(target.parent_path())) {
    if (entry.path().filename().string().rfind(prefix, 0) != 0) continue;
    ++found;
    std::filesystem::remove(entry.path());
  }
  return found;
}

bool temporary_exists(const std::filesystem::path& target) {
  const std::string prefix = "." + target.filename().string() + ".tmp-";
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(target.parent_path(), ec)) {
    if (entry.path().filename().string().rfind(prefix, 0) == 0) return true;
  }
  return false;
}

TEST(AtomicSave, KilledMidSaveLeavesTheOldOrTheNewFile) {
  test::TempDir dir("atomic");
  const auto target = dir / "work.vimg";
  const Image old_image = many_dots(10, 0.5);
  const Image new_image = many_dots(60000, 1.0);  // about 5 MB of XML
  const std::string old_bytes = write_image_xml(old_image);
  const std::string new_bytes = write_image_xml(new_image);
  int saw_old = 0;
  int saw_new = 0;
  int killed_mid_write = 0;  // kills that left a temporary: the save was under way
  // A child saves the big image again and again; it is killed once `ready` holds, and the target
  // must then be the old file or the complete new one.
  auto kill_saver_when = [&](auto ready) {
    ASSERT_FALSE(save_image_file(old_image, target).has_value());
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
      for (;;) save_image_file(new_image, target);
    }
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(120);
    while (!ready() && std::chrono::steady_clock::now() < give_up) std::this_thread::sleep_for(std::chrono::microseconds(100));
    ::kill(child, SIGKILL);
    int status = 0;
    ::waitpid(child, &status, 0);
    ASSERT_TRUE(WIFSIGNALED(status));
    killed_mid_write += take_leftover_temporaries(target) > 0 ? 1 : 0;
    const std::string now = test::read_text_file(target);
    if (now == old_bytes) {
      ++saw_old;
    } else if (now == new_bytes) {
      ++saw_new;
    } else {
      FAIL() << "torn file of " << now.size() << " bytes (old " << old_bytes.size() << ", new " << new_bytes.size() << ")";
    }
  };
  // Killed as soon as the temporary file appears (the first save under way), then as soon as the
  // target has been replaced once and a temporary is there again (a later save under way): each
  // kill lands mid-write, whatever the machine's speed.
  for (int round = 0; round < 5; ++round) {
    SCOPED_TRACE("round " + std::to_string(round));
    kill_saver_when([&] { return temporary_exists(target); });
    std::error_code ec;
    bool replaced = false;
    kill_saver_when([&] {
      replaced = replaced || std::filesystem::file_size(target, ec) == new_bytes.size();
      return replaced && temporary_exists(target);
    });
  }
  // Every kill should land mid-write; on a machine that deschedules this process for longer than a
  // save between seeing the temporary and the kill, a few may not. At least one must.
  EXPECT_GE(killed_mid_write, 1);
  EXPECT_GE(saw_new, 1);  // killed after a replacement
  EXPECT_EQ(saw_old + saw_new, 10);
  std::printf("%d of 10 kills landed mid-write\n", killed_mid_write);
  // Last round: kill only once a save has completed, then the file must be the complete new one.
  std::error_code ec;
  kill_saver_when([&] { return std::filesystem::file_size(target, ec) == new_bytes.size(); });
  EXPECT_EQ(test::read_text_file(target), new_bytes);
}

TEST(AtomicSave, FailureLeavesTheTargetUntouchedAndNoTemporaryFile) {
  test::TempDir dir("atomic_fail");
  const auto target = dir / "keep.vimg";
  test::write_text_file(target, "original");
  // A directory where the file should be: rename fails, the temporary file is removed.
  const auto blocked = dir / "blocked.vimg";
  std::filesystem::create_directories(blocked / "inside");
  const auto error = write_file_atomically(blocked, "new content");
  ASSERT_TRUE(error.has_value());
  EXPECT_NE(error->find("blocked.vimg"), std::string::npos) << *error;
  int entries = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir.path())) {
    (void)entry;
    ++entries;
  }
  EXPECT_EQ(entries, 2) << "only keep.vimg and blocked.vimg remain";
  EXPECT_EQ(test::read_text_file(target), "original");
  // A missing directory is an error naming the path.
  const auto missing = write_file_atomically(dir / "no" / "such" / "dir.vimg", "x");
  ASSERT_TRUE(missing.has_value());
  EXPECT_NE(missing->find("dir.vimg"), std::string::npos);
}

TEST(AtomicSave, AnImageWhoseTextNoReaderAcceptsIsNotSaved) {
  test::TempDir dir("too_long");
  Image image = many_dots(3, 0.5);
  image.meta = Meta{};
  image.meta->description = std::string(kMaxImageFileBytes, 'a');  // the text around it passes the limit
  for (const char* name : {"long.vimg", "long.png"}) {
    SaveOptions options;
    options.scale_px_per_mm = 1.0;
    const auto error = save_image_file(image, dir / name, options);
    ASSERT_TRUE(error.has_value()) << name;
    EXPECT_NE(error->find(std::string(name) + ": the XML text of this image is"), std::string::npos) << *error;
    EXPECT_NE(error->find("(limit " + std::to_string(kMaxImageFileBytes) + ")"), std::string::npos) << *error;
    EXPECT_TRUE(std::filesystem::is_empty(dir.path())) << name;
  }
  image.meta->description = std::string(1000, 'a');
  EXPECT_FALSE(save_image_file(image, dir / "short.vimg").has_value());
}

TEST(AtomicSave, AnImageWhoseTextHoldsAControlCharacterIsNotSaved) {
  // XML cannot hold ESC, even as a reference: an id set by a program is refused at save, never
  // written into a file that no reader accepts.
  test::TempDir dir("control");
  Image image = many_dots(3, 0.5);
  image.children[1].id = "dot \x1b[31m";
  for (const char* name : {"c.vimg", "c.png"}) {
    SaveOptions options;
    options.scale_px_per_mm = 1.0;
    const auto error = save_image_file(image, dir / name, options);
    ASSERT_TRUE(error.has_value()) << name;
    EXPECT_NE(error->find(std::string(name) + ": the XML text of this image could not be opened again: line "),
              std::string::npos)
        << *error;
    EXPECT_NE(error->find("a control character (byte 0x1B) at offset"), std::string::npos) << *error;
    EXPECT_TRUE(std::filesystem::is_empty(dir.path())) << name;
  }
}

TEST(AtomicSave, AnImageWithMoreElementsThanAReaderAcceptsIsNotSaved) {
  test::TempDir dir("elements");
  // With the XML declaration and the root, one node more than a reader accepts.
  Image image = many_dots(static_cast<int>(kMaxXmlElements) - 1, 0.5);
  for (const char* name : {"e.vimg", "e.png"}) {
    SaveOptions options;
    options.scale_px_per_mm = 0.1;
    const auto error = save_image_file(image, dir / name, options);
    ASSERT_TRUE(error.has_value()) << name;
    EXPECT_NE(error->find("(limit " + std::to_string(kMaxXmlElements) + ")"), std::string::npos) << *error;
    EXPECT_TRUE(std::filesystem::is_empty(dir.path())) << name;
  }
  image.children.pop_back();
  EXPECT_FALSE(save_image_file(image, dir / "fits.vimg").has_value());
}

TEST(AtomicSave, ReplacesAnExistingFileCompletely) {
  test::TempDir dir("atomic_replace");
  const auto target = dir / "f.vimg";
  test::write_text_file(target, std::string(100000, 'x'));
  ASSERT_FALSE(write_file_atomically(target, "short").has_value());
  EXPECT_EQ(test::read_text_file(target), "short");
}

TEST(AtomicSave, KeepsThePermissionsOfTheFileItReplaces) {
  test::TempDir dir("atomic_mode");
  const auto target = dir / "private.vimg";
  test::write_text_file(target, "old");
  std::filesystem::permissions(target, std::filesystem::perms::owner_read | std::filesystem::perms::owner_write);
  ASSERT_FALSE(write_file_atomically(target, "new").has_value());
  EXPECT_EQ(test::read_text_file(target), "new");
  EXPECT_EQ(std::filesystem::status(target).permissions() & std::filesystem::perms::all,
            std::filesystem::perms::owner_read | std::filesystem::perms::owner_write);
}

TEST(AtomicFileWriter, StreamsChunksAndAppearsOnlyAtCommit) {
  test::TempDir dir("atomic_stream");
  const auto target = dir / "log.csv";
  test::write_text_file(target, "previous");
  AtomicFileWriter writer(target);
  ASSERT_TRUE(writer.ok()) << writer.error();
  EXPECT_TRUE(std::filesystem::exists(writer.temporary_path()));
  EXPECT_EQ(writer.temporary_path().parent_path(), target.parent_path());
  for (int i = 0; i < 1000; ++i) ASSERT_TRUE(writer.write("row " + std::to_string(i) + "\n"));
  EXPECT_EQ(test::read_text_file(target), "previous");  // readers still see the old file
  const auto temp = writer.temporary_path();
  ASSERT_FALSE(writer.commit().has_value());
  EXPECT_FALSE(std::filesystem::exists(temp));
  const std::string text = test::read_text_file(target);
  EXPECT_EQ(text.substr(0, 6), "row 0\n");
  EXPECT_EQ(text.substr(text.size() - 8), "row 999\n");
}

TEST(AtomicFileWriter, AbandonedWriterLeavesTheTargetAndNoTemporary) {
  test::TempDir dir("atomic_abandon");
  const auto target = dir / "out.csv";
  test::write_text_file(target, "keep me");
  {
    AtomicFileWriter writer(target);
    ASSERT_TRUE(writer.write("half a fi"));
  }
  EXPECT_EQ(test::read_text_file(target), "keep me");
  int entries = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir.path())) entries += entry.path() == target ? 0 : 1;
  EXPECT_EQ(entries, 0);
}

TEST(AtomicFileWriter, NeverFollowsASymlinkPlantedAtItsTemporaryName) {
  test::TempDir dir("atomic_symlink");
  const auto victim = dir / "victim.txt";
  test::write_text_file(victim, "precious");
  const auto target = dir / "out.csv";
  // Plant symlinks at the next temporary names this process will try.
  AtomicFileWriter probe(target);
  ASSERT_TRUE(probe.ok());
  const std::string name = probe.temporary_path().filename().string();
  probe.abort();
  const auto dash = name.rfind('-');
  const unsigned next = static_cast<unsigned>(std::stoul(name.substr(dash + 1))) + 1;
  const auto planted = dir / (name.substr(0, dash + 1) + std::to_string(next));
  std::filesystem::create_symlink(victim, planted);
  AtomicFileWriter writer(target);
  EXPECT_FALSE(writer.ok());
  EXPECT_FALSE(writer.write("overwrite?"));
  EXPECT_TRUE(writer.commit().has_value());
  EXPECT_EQ(test::read_text_file(victim), "precious");
  EXPECT_TRUE(std::filesystem::is_symlink(planted));
}

}  // namespace
}  // namespace vimg
