// The one bounded reader: only regular files within the limit, and never a hang.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>

#include "storage/read_file.hpp"
#include "storage_test_support.hpp"

namespace vimg {
namespace {

TEST(ReadRegularFile, ReadsARegularFileWithinTheLimit) {
  test::TempDir dir("read_ok");
  test::write_text_file(dir / "a.txt", "hello");
  const FileReadResult r = read_regular_file(dir / "a.txt", 5);
  ASSERT_TRUE(r.bytes) << r.error;
  EXPECT_EQ(*r.bytes, "hello");
  test::write_text_file(dir / "e.txt", "");
  const FileReadResult empty = read_regular_file(dir / "e.txt", 5);
  ASSERT_TRUE(empty.bytes);
  EXPECT_TRUE(empty.bytes->empty());
}

TEST(ReadRegularFile, RefusesWhatIsLargerThanTheLimitBeforeReading) {
  test::TempDir dir("read_big");
  test::write_text_file(dir / "big.txt", std::string(2048, 'x'));
  const FileReadResult r = read_regular_file(dir / "big.txt", 1024);
  EXPECT_FALSE(r.bytes);
  EXPECT_EQ(r.error, "is larger than 1 KiB (limit 1024 bytes)");
}

TEST(ReadRegularFile, RefusesDevicesFifosAndFoldersWithoutBlocking) {
  test::TempDir dir("read_special");
  const FileReadResult zero = read_regular_file("/dev/zero", 1024);
  EXPECT_FALSE(zero.bytes);
  EXPECT_EQ(zero.error, "is not a regular file (a character device)");
  const auto fifo = dir / "pipe";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const FileReadResult pipe = read_regular_file(fifo, 1024);  // would block forever without O_NONBLOCK
  EXPECT_FALSE(pipe.bytes);
  EXPECT_EQ(pipe.error, "is not a regular file (a FIFO)");
  const FileReadResult folder = read_regular_file(dir.path(), 1024);
  EXPECT_FALSE(folder.bytes);
  EXPECT_EQ(folder.error, "is not a regular file (a directory)");
  const FileReadResult missing = read_regular_file(dir / "missing", 1024);
  EXPECT_FALSE(missing.bytes);
  EXPECT_EQ(missing.error, "cannot open: No such file or directory");
}

}  // namespace
}  // namespace vimg
