// NRRD files that other projects wrote (tests/data/nrrd/README.md names their origin): each loads
// through teem and gives the voxel values and geometry that the project's own tests assert.
// Then the checks vibroimage keeps on top of teem: confined data files, compression bombs.
#include <bzlib.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>
#include <zlib.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "storage/atomic_file.hpp"
#include "storage/volume/nrrd.hpp"
#include "storage/volume/nrrd_volume.hpp"

namespace vimg {
namespace {

namespace fs = std::filesystem;
const fs::path kData = fs::path(VIMG_TEST_DATA_DIR) / "nrrd";

std::string first_message(const std::vector<Diagnostic>& d) { return d.empty() ? std::string() : d.front().to_string(); }

std::string read_bytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::vector<float> one_to_27() {
  std::vector<float> v;
  for (int i = 1; i <= 27; ++i) v.push_back(static_cast<float>(i));
  return v;
}

// pynrrd test_read_header_and_ascii_1d_data: unsigned char, sizes [27], spacings [1.0458], data 1..27.
TEST(NrrdFiles, PynrrdAscii1d) {
  for (const char* name : {"test1d_ascii.nrrd", "test_customFields.nrrd"}) {
    const NrrdVolumeResult r = load_nrrd_volume(kData / "pynrrd" / name);
    ASSERT_TRUE(r.volume) << first_message(r.diagnostics);
    EXPECT_EQ(r.volume->type, "unsigned char");
    ASSERT_EQ(r.volume->axes.size(), 1u);
    EXPECT_EQ(r.volume->axes[0].size, 27u);
    EXPECT_DOUBLE_EQ(r.volume->axes[0].spacing, 1.0458);
    EXPECT_EQ(r.volume->axes[0].kind, "domain");
    EXPECT_EQ(r.volume->values, one_to_27());
  }
}

// pynrrd test_read_header_and_ascii_2d_data: unsigned short, sizes [3, 9], spacings [1.0458, 2],
// data == arange(1, 28).reshape(3, 9, order='F'), i.e. data[i, j] = 1 + i + 3 j, i fastest.
// The same values through teem's hex and big-endian bzip2 encodings (files made with teem-unu).
TEST(NrrdFiles, PynrrdAscii2dAndItsHexAndBzip2Copies) {
  for (const fs::path& p : {kData / "pynrrd" / "test2d_ascii.nrrd", kData / "teem" / "test2d_hex.nrrd",
                           kData / "teem" / "test2d_double_big_bz2.nrrd"}) {
    const NrrdVolumeResult r = load_nrrd_volume(p);
    ASSERT_TRUE(r.volume) << first_message(r.diagnostics);
    ASSERT_EQ(r.volume->axes.size(), 2u);
    EXPECT_EQ(r.volume->axes[0].size, 3u);
    EXPECT_EQ(r.volume->axes[1].size, 9u);
    EXPECT_DOUBLE_EQ(r.volume->axes[0].spacing, 1.0458);
    EXPECT_DOUBLE_EQ(r.volume->axes[1].spacing, 2.0);
    for (std::size_t i = 0; i < 3; ++i) {
      for (std::size_t j = 0; j < 9; ++j) EXPECT_EQ(r.volume->values[i + 3 * j], static_cast<float>(1 + i + 3 * j)) << p;
    }
  }
  EXPECT_EQ(load_nrrd_volume(kData / "teem" / "test2d_hex.nrrd").volume->encoding, "hex");
  EXPECT_EQ(load_nrrd_volume(kData / "teem" / "test2d_double_big_bz2.nrrd").volume->type, "double");
}

// pynrrd's BallBinary tests: the detached header (raw data file, and `byte skip: -1`), the attached
// raw, gzip, bzip2 and gzip-after-three-skipped-lines files all give the raw file's int16 samples,
// 30x30x30 with unit space directions and origin 0 in a left-posterior-superior space.
TEST(NrrdFiles, PynrrdBallInEveryEncodingGivesTheRawSamples) {
  const std::string raw = read_bytes(kData / "pynrrd" / "BallBinary30x30x30.raw");
  ASSERT_EQ(raw.size(), 27000u * 2u);
  std::vector<float> expected(27000);
  for (std::size_t i = 0; i < expected.size(); ++i) {
    const auto lo = static_cast<unsigned char>(raw[2 * i]);
    const auto hi = static_cast<unsigned char>(raw[2 * i + 1]);
    expected[i] = static_cast<float>(static_cast<std::int16_t>(lo | (hi << 8)));
  }
  for (const char* name : {"BallBinary30x30x30.nhdr", "BallBinary30x30x30_byteskip_minus_one.nhdr", "BallBinary30x30x30.nrrd",
                           "BallBinary30x30x30_gz.nrrd", "BallBinary30x30x30_bz2.nrrd", "BallBinary30x30x30_gz_lineskip.nrrd"}) {
    const NrrdLoadResult r = load_nrrd_file(kData / "pynrrd" / name);
    ASSERT_TRUE(r.scalar) << name << ": " << first_message(r.diagnostics);
    EXPECT_EQ(r.scalar->values(), expected) << name;
    const GridGeometry& g = r.scalar->geometry();
    EXPECT_EQ(g.size, (GridSize{30, 30, 30})) << name;
    EXPECT_NEAR(g.spacing_m.x, 1e-3, 1e-15);
    EXPECT_NEAR(g.spacing_m.z, 1e-3, 1e-15);
    EXPECT_EQ(g.origin_m, Vec3{});
    const NrrdVolumeResult v = load_nrrd_volume(kData / "pynrrd" / name);
    ASSERT_TRUE(v.volume);
    EXPECT_EQ(v.volume->type, "short");
    EXPECT_EQ(v.volume->space_dimension, 3u);
    EXPECT_EQ(v.volume->axes[1].space_direction, (std::vector<double>{0, 1, 0}));
  }
  EXPECT_EQ(load_nrrd_volume(kData / "pynrrd" / "BallBinary30x30x30_bz2.nrrd").volume->encoding, "bzip2");
}

// NRRD.jl test3d_units_range_axes.nhdr: axes R 10:2:14 mm, A 12:2:16 mm, S 100:5:110 mm, UInt8.
TEST(NrrdFiles, NrrdJlRangeAxesGiveOriginAndSpacingInMillimetres) {
  const NrrdLoadResult r = load_nrrd_file(kData / "nrrdjl" / "range_axes" / "test3d_units_range_axes.nhdr");
  ASSERT_TRUE(r.scalar) << first_message(r.diagnostics);
  const GridGeometry& g = r.scalar->geometry();
  EXPECT_EQ(g.size, (GridSize{3, 3, 3}));
  EXPECT_NEAR(g.origin_m.x, 0.010, 1e-12);
  EXPECT_NEAR(g.origin_m.y, 0.012, 1e-12);
  EXPECT_NEAR(g.origin_m.z, 0.100, 1e-12);
  EXPECT_NEAR(g.far_corner_m().x, 0.014, 1e-12);
  EXPECT_NEAR(g.far_corner_m().y, 0.016, 1e-12);
  EXPECT_NEAR(g.far_corner_m().z, 0.110, 1e-12);
  for (std::size_t i = 0; i < 27; ++i) EXPECT_EQ(r.scalar->values()[i], static_cast<float>(i));  // dummy.raw: bytes 0..26
}

// NRRD.jl test3dlist_origin.nhdr: axes R 1:3, A 2:4, S 3:5 and a list axis 0:1. It is not a grid
// a scene can use (its first axis is space, not a vector), and the message names the kinds line.
TEST(NrrdFiles, NrrdJlListAxisLoadsAsAVolumeButNotAsAGrid) {
  const fs::path p = kData / "nrrdjl" / "list_origin" / "test3dlist_origin.nhdr";
  const NrrdVolumeResult v = load_nrrd_volume(p);
  ASSERT_TRUE(v.volume) << first_message(v.diagnostics);
  ASSERT_EQ(v.volume->axes.size(), 4u);
  EXPECT_EQ(v.volume->axes[3].size, 2u);
  EXPECT_EQ(v.volume->axes[3].kind, "list");
  EXPECT_EQ(v.volume->space_origin, (std::vector<double>{1, 2, 3}));
  EXPECT_EQ(v.volume->values.back(), 53.0f);
  EXPECT_EQ(first_message(load_nrrd_file(p).diagnostics),
            p.string() + ":9: error: the first axis of a vector volume must have a vector kind, got 'space'");
}

class NrrdDataFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("vimg_nrrd_data_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "sub");
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path write(const fs::path& rel, const std::string& bytes) {
    EXPECT_FALSE(write_file_atomically(dir_ / rel, bytes).has_value());
    return dir_ / rel;
  }
  static std::string header(const std::string& data_file) {
    return "NRRD0004\ntype: uchar\ndimension: 3\nsizes: 2 1 1\nencoding: raw\ndata file: " + data_file + "\n";
  }
  fs::path dir_;
};

TEST_F(NrrdDataFiles, ADataFileOutsideTheHeadersFolderIsRefusedUnlessAllowed) {
  write("outside.raw", "ab");
  const fs::path h = write("sub/v.nhdr", header("../outside.raw"));
  const NrrdLoadResult r = load_nrrd_file(h);
  EXPECT_FALSE(r.ok());
  EXPECT_EQ(first_message(r.diagnostics).rfind(h.string() + ":6: error: field 'data file' = '../outside.raw': leads outside the header's folder", 0), 0u)
      << first_message(r.diagnostics);
  NamedFileOptions allow;
  allow.allow_outside_folder = true;
  const NrrdLoadResult allowed = load_nrrd_file(h, allow);
  ASSERT_TRUE(allowed.scalar) << first_message(allowed.diagnostics);
  EXPECT_EQ(allowed.scalar->values(), (std::vector<float>{'a', 'b'}));
  const fs::path absolute = write("sub/abs.nhdr", header((dir_ / "outside.raw").string()));
  EXPECT_FALSE(load_nrrd_file(absolute).ok());
}

TEST_F(NrrdDataFiles, ADataFileThatIsAFifoASymlinkOrMissingIsRefusedWithoutReading) {
  ASSERT_EQ(::mkfifo((dir_ / "fifo.raw").c_str(), 0600), 0);
  const fs::path fifo = write("fifo.nhdr", header("fifo.raw"));
  EXPECT_EQ(first_message(load_nrrd_file(fifo).diagnostics),
            fifo.string() + ":6: error: field 'data file' = 'fifo.raw': is not a regular file (a FIFO)");
  write("real.raw", "ab");
  fs::create_symlink(dir_ / "real.raw", dir_ / "link.raw");
  EXPECT_FALSE(load_nrrd_file(write("link.nhdr", header("link.raw"))).ok());
  const fs::path missing = write("missing.nhdr", header("nowhere.raw"));
  EXPECT_NE(first_message(load_nrrd_file(missing).diagnostics).find(":6: error: field 'data file' = 'nowhere.raw': "), std::string::npos);
  EXPECT_TRUE(load_nrrd_file(write("real.nhdr", header("real.raw"))).ok());
}

TEST_F(NrrdDataFiles, DetachedDataOfTheWrongSizeNamesTheDataFile) {
  write("short.raw", "a");
  const fs::path h = write("short.nhdr", header("short.raw"));
  EXPECT_EQ(first_message(load_nrrd_file(h).diagnostics),
            h.string() + ":6: error: data file 'short.raw': data holds 1 bytes, the header needs 2");
}

// zlib-wrapped deflate: the reader takes gzip or zlib streams.
std::string deflated(const std::string& raw) {
  uLongf length = compressBound(static_cast<uLong>(raw.size()));
  std::string out(length, '\0');
  EXPECT_EQ(compress2(reinterpret_cast<Bytef*>(out.data()), &length, reinterpret_cast<const Bytef*>(raw.data()),
                      static_cast<uLong>(raw.size()), 9), Z_OK);
  out.resize(length);
  return out;
}

std::string bzip2(std::string raw) {
  std::string out(raw.size() / 50 + 1024, '\0');
  auto length = static_cast<unsigned>(out.size());
  EXPECT_EQ(BZ2_bzBuffToBuffCompress(out.data(), &length, raw.data(), static_cast<unsigned>(raw.size()), 9, 0, 0), BZ_OK);
  out.resize(length);
  return out;
}

// A compression bomb: a few kilobytes that inflate to 64 MiB, behind a header declaring 4 bytes.
TEST(NrrdBombs, CompressedDataInflatingPastTheDeclaredSizeIsRefused) {
  const std::string zeros(64u << 20, '\0');
  const std::string head = "NRRD0004\ntype: uchar\ndimension: 3\nsizes: 2 2 1\nencoding: ";
  EXPECT_EQ(first_message(parse_nrrd(head + "gzip\n\n" + deflated(zeros), "bomb.nrrd").diagnostics),
            "bomb.nrrd:7: error: gzip data inflates to more than the 4 bytes the header declares");
  EXPECT_EQ(first_message(parse_nrrd(head + "bzip2\n\n" + bzip2(zeros), "bomb.nrrd").diagnostics),
            "bomb.nrrd:7: error: bzip2 data inflates to more than the 4 bytes the header declares");
  EXPECT_EQ(first_message(parse_nrrd(head + "bzip2\n\n" + bzip2("abc"), "short.nrrd").diagnostics),
            "short.nrrd:7: error: data holds 3 bytes, the header needs 4");
  const NrrdLoadResult ok = parse_nrrd(head + "bzip2\n\n" + bzip2("abcd"), "ok.nrrd");
  ASSERT_TRUE(ok.scalar) << first_message(ok.diagnostics);
  EXPECT_EQ(ok.scalar->values(), (std::vector<float>{'a', 'b', 'c', 'd'}));
}

}  // namespace
}  // namespace vimg
