// Atomic save (spec section 4): a process killed mid-save leaves the old file or the complete new
// one, never a torn file.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <string>
#include <thread>

#include "storage/atomic_file.hpp"
#include "storage/image_io.hpp"
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

TEST(AtomicSave, KilledMidSaveLeavesTheOldOrTheNewFile) {
  test::TempDir dir("atomic");
  const auto target = dir / "work.vimg";
  const Image old_image = many_dots(10, 0.5);
  const Image new_image = many_dots(60000, 1.0);  // about 5 MB of XML
  const std::string old_bytes = write_image_xml(old_image);
  const std::string new_bytes = write_image_xml(new_image);
  int saw_old = 0;
  int saw_new = 0;
  // Kill times spread over one save's duration and beyond (the child saves in a loop).
  const auto start = std::chrono::steady_clock::now();
  ASSERT_FALSE(save_image_file(new_image, dir / "probe.vimg").has_value());
  const double save_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  for (const double fraction : {0.0, 0.05, 0.1, 0.2, 0.3, 0.45, 0.6, 0.75, 0.9, 1.0, 1.1, 1.3, 1.7, 2.5}) {
    const auto delay_ms = static_cast<long>(fraction * save_ms);
    SCOPED_TRACE("kill after " + std::to_string(delay_ms) + " ms");
    ASSERT_FALSE(save_image_file(old_image, target).has_value());
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
      // Save the big image again and again until killed.
      for (;;) save_image_file(new_image, target);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(delay_ms));
    ::kill(child, SIGKILL);
    int status = 0;
    ::waitpid(child, &status, 0);
    ASSERT_TRUE(WIFSIGNALED(status));
    const std::string now = test::read_text_file(target);
    if (now == old_bytes) {
      ++saw_old;
    } else if (now == new_bytes) {
      ++saw_new;
    } else {
      FAIL() << "torn file of " << now.size() << " bytes (old " << old_bytes.size() << ", new " << new_bytes.size() << ")";
    }
  }
  EXPECT_EQ(saw_old + saw_new, 14);
  // Last round: kill only once a save has completed (polling, whatever the machine's load), then
  // the file must be the complete new one.
  ASSERT_FALSE(save_image_file(old_image, target).has_value());
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    for (;;) save_image_file(new_image, target);
  }
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  std::error_code ec;
  while (std::filesystem::file_size(target, ec) != new_bytes.size() && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  ::kill(child, SIGKILL);
  int status = 0;
  ::waitpid(child, &status, 0);
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

TEST(AtomicSave, ReplacesAnExistingFileCompletely) {
  test::TempDir dir("atomic_replace");
  const auto target = dir / "f.vimg";
  test::write_text_file(target, std::string(100000, 'x'));
  ASSERT_FALSE(write_file_atomically(target, "short").has_value());
  EXPECT_EQ(test::read_text_file(target), "short");
}

}  // namespace
}  // namespace vimg
