// NRRD volumes against their limits (docs/limits.md, "Volumes"): a header declaring more data than
// kMaxVolumeDataBytes is refused before anything is allocated, gzip data is never inflated past the
// declared size, and files that are not regular (FIFOs, devices) or too large are refused without
// blocking or reading them.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>
#include <zlib.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "storage/limits.hpp"
#include "storage/volume/nrrd.hpp"
#include "storage_test_support.hpp"

namespace vimg {
namespace {

std::string first_message(const NrrdLoadResult& r) { return r.diagnostics.empty() ? "" : r.diagnostics[0].to_string(); }

std::string gzip(const std::string& raw) {
  z_stream z{};
  EXPECT_EQ(deflateInit2(&z, 9, Z_DEFLATED, 15 + 16, 9, Z_DEFAULT_STRATEGY), Z_OK);
  std::string out(deflateBound(&z, static_cast<uLong>(raw.size())) + 64, '\0');
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(raw.data()));
  z.avail_in = static_cast<uInt>(raw.size());
  z.next_out = reinterpret_cast<Bytef*>(out.data());
  z.avail_out = static_cast<uInt>(out.size());
  EXPECT_EQ(deflate(&z, Z_FINISH), Z_STREAM_END);
  out.resize(out.size() - z.avail_out);
  deflateEnd(&z);
  return out;
}

TEST(NrrdLimits, DeclaredDataOverTheByteLimitIsRefusedAtTheSizesLine) {
  // 2^27 doubles: within the sample limit, but 1 GiB of data.
  const std::string text = "NRRD0004\ntype: double\ndimension: 3\nsizes: 512 512 512\nendian: little\nencoding: raw\n\nxyz";
  EXPECT_EQ(first_message(parse_nrrd(text, "d.nrrd")),
            "d.nrrd:4: error: the header declares 1073741824 bytes of data (limit 536870912)");
}

// teem copies a bad field's line into a fixed stack buffer for its message (a line of 963 bytes
// overflowed it; found by the fuzzer). Every field, with bad values of the longest length allowed,
// gives an error and returns; one byte more is refused before teem sees the line.
TEST(NrrdLimits, EveryFieldLineUpToTheLimitFailsCleanlyAndLongerIsRefused) {
  const std::vector<std::string> fields = {
      "type", "dimension", "space", "space dimension", "sizes", "spacings", "thicknesses", "axis mins", "axis maxs",
      "centers", "centerings", "kinds", "space directions", "space origin", "measurement frame", "encoding", "endian",
      "byte skip", "line skip", "old min", "old max", "no such field"};
  for (const std::string& field : fields) {
    const bool has_type = field == "type", has_dimension = field == "dimension" || field == "type";
    const std::string head = std::string("NRRD0004\n") + (has_type ? "" : "type: uchar\n") + (has_dimension ? "" : "dimension: 3\n") +
                             (field.rfind("space", 0) == 0 ? "" : "space: RAS\n");
    for (const char filler : {'x', '1', '('}) {
      for (const std::size_t length : {kMaxNrrdFieldLineBytes, kMaxNrrdFieldLineBytes + 1}) {
        std::string line = field + ": " + std::string(length - field.size() - 2, filler);
        // With ':=' inside, teem still reads the line as the field it starts with (a key/value line
        // for us, once; found by the fuzzer).
        if (filler == '(') line.replace(line.size() - 4, 2, ":=");
        const NrrdLoadResult r = parse_nrrd(head + line + "\nsizes: 1 1 1\nencoding: raw\n\n\x01", "f.nrrd");
        EXPECT_FALSE(r.ok()) << line.substr(0, 40);
        const bool refused = first_message(r).find("(limit " + std::to_string(kMaxNrrdFieldLineBytes) + ")") != std::string::npos;
        EXPECT_EQ(refused, length > kMaxNrrdFieldLineBytes) << field << " '" << filler << "' " << length << ": " << first_message(r);
      }
    }
  }
}

TEST(NrrdLimits, AKeyValueLineLongerThanTheLimitIsRefused) {
  const std::string head = "NRRD0004\ntype: uchar\ndimension: 3\nsizes: 1 1 1\nencoding: raw\n";
  for (const std::size_t length : {kMaxNrrdFieldLineBytes, kMaxNrrdFieldLineBytes + 1}) {
    const std::string line = "note:=" + std::string(length - 6, 'v');
    const NrrdLoadResult r = parse_nrrd(head + line + "\n\n\x01", "kv.nrrd");
    EXPECT_EQ(r.ok(), length == kMaxNrrdFieldLineBytes) << length << ": " << first_message(r);
    if (!r.ok()) {
      EXPECT_EQ(first_message(r), "kv.nrrd:6: error: the field line is longer than 800 bytes (limit 800)");
    }
  }
  // A comment is not a field: teem skips it, so it may be longer.
  EXPECT_TRUE(parse_nrrd(head + "# " + std::string(4 * kMaxNrrdFieldLineBytes, 'c') + "\n\n\x01", "c.nrrd").ok());
}

// teem scans each ASCII sample into a fixed 1 KiB buffer (fscanf "%s"): a longer one overflowed
// it, and the fuzzer found the wild pointer that followed. Held to kMaxNrrdAsciiSampleBytes.
TEST(NrrdLimits, AnAsciiSampleLongerThanTheLimitIsRefused) {
  const std::string head = "NRRD0004\ntype: float\ndimension: 3\nsizes: 2 1 1\nencoding: ascii\n\n";
  const std::string at_limit = "1." + std::string(kMaxNrrdAsciiSampleBytes - 2, '5');
  EXPECT_TRUE(parse_nrrd(head + at_limit + " 2\n", "a.nrrd").ok()) << first_message(parse_nrrd(head + at_limit + " 2\n", "a.nrrd"));
  for (const std::size_t length : {kMaxNrrdAsciiSampleBytes + 1, std::size_t{5000}}) {
    const NrrdLoadResult r = parse_nrrd(head + "1 " + std::string(length, 'c') + "\n", "long.nrrd");
    EXPECT_FALSE(r.ok());
    EXPECT_NE(first_message(r).find("an ASCII sample is longer than 256 bytes (limit 256)"), std::string::npos) << first_message(r);
  }
}

TEST(NrrdLimits, GzipDataLongerThanDeclaredIsRefused) {
  // 64 MiB of zeros deflate to about 64 KB; the header declares 4 bytes.
  const std::string head = "NRRD0004\ntype: uchar\ndimension: 3\nsizes: 2 2 1\nencoding: gzip\n\n";
  const NrrdLoadResult r = parse_nrrd(head + gzip(std::string(64 * kMiB, '\0')), "bomb.nrrd");
  EXPECT_FALSE(r.ok());
  EXPECT_EQ(first_message(r), "bomb.nrrd:7: error: gzip data inflates to more than the 4 bytes the header declares");
}

TEST(NrrdLimits, GzipDataOfExactlyTheDeclaredSizeLoadsInAnyChunking) {
  // 2-byte samples against the inflater's odd-sized pieces: every sample must still come out whole.
  std::string raw;
  for (int i = 0; i < 300000; ++i) {
    const auto v = static_cast<std::int16_t>((i * 37) % 20001 - 10000);
    raw += static_cast<char>(v & 0xFF);
    raw += static_cast<char>((v >> 8) & 0xFF);
  }
  const std::string head = "NRRD0004\ntype: short\ndimension: 3\nsizes: 100 100 30\nendian: little\nencoding: gzip\n\n";
  const NrrdLoadResult r = parse_nrrd(head + gzip(raw), "ok.nrrd");
  ASSERT_TRUE(r.scalar.has_value()) << first_message(r);
  for (int i : {0, 1, 12345, 299999}) {
    EXPECT_EQ(r.scalar->values()[static_cast<std::size_t>(i)], static_cast<float>((i * 37) % 20001 - 10000)) << i;
  }
}

TEST(NrrdLimits, AFifoIsRefusedWithoutBlocking) {
  test::TempDir dir("nrrd_fifo");
  const auto fifo = dir / "v.nrrd";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  NrrdLoadResult r;
  {
    const test::FifoReleaser release(fifo);
    r = load_nrrd_file(fifo);
  }
  EXPECT_EQ(first_message(r), fifo.string() + ": error: is not a regular file (a FIFO)");
}

TEST(NrrdLimits, DevicesAndFilesOverTheSizeLimitAreNotRead) {
  EXPECT_EQ(first_message(load_nrrd_file("/dev/zero")), "/dev/zero: error: is not a regular file (a character device)");
  test::TempDir dir("nrrd_big");
  const auto big = dir / "big.nrrd";
  { std::ofstream(big).put('N'); }
  std::filesystem::resize_file(big, kMaxVolumeFileBytes + 1);  // sparse: nothing is written
  EXPECT_EQ(first_message(load_nrrd_file(big)), big.string() + ": error: is larger than 1024 MiB (limit 1073741824 bytes)");
}

}  // namespace
}  // namespace vimg
