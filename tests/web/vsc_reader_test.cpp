// The .vsc reader is a parser of untrusted bytes (a page may be handed any file): every damaged input
// is an error with a byte offset, never a crash, a huge allocation or an out-of-range value.
#include <gtest/gtest.h>

#include <cstring>

#include "player/scene.hpp"
#include "tests/web/web_test_support.hpp"
#include "storage/vsc/vsc_format.hpp"

namespace vimg {
namespace {

std::string smiley_vsc() {
  return write_vsc({test::load_example(test::source_dir() / "assets/examples/smiley.vimg"), ResponseParams{}});
}

void put_u32(std::string& bytes, std::size_t at, std::uint32_t v) { std::memcpy(bytes.data() + at, &v, 4); }

VscImage one_element(Element e) {
  VscImage v;
  v.image.children.push_back(std::move(e));
  return v;
}

TEST(VscReader, EveryTruncationIsAnError) {
  const std::string bytes = smiley_vsc();
  for (std::size_t n = 0; n < bytes.size(); ++n) {
    std::string cut = bytes.substr(0, n);
    if (n >= vsc::kHeaderBytes) put_u32(cut, 12, static_cast<std::uint32_t>(n - vsc::kHeaderBytes));  // a consistent header
    const VscReadResult r = read_vsc(cut, "cut.vsc");
    EXPECT_FALSE(r.image.has_value()) << n;
    EXPECT_EQ(r.error.rfind("cut.vsc: error: byte ", 0), 0u) << r.error;
  }
}

TEST(VscReader, EveryDamagedByteGivesAnErrorOrAnImageThatCompiles) {
  const std::string bytes = smiley_vsc();
  for (std::size_t i = 0; i < bytes.size(); ++i) {
    for (const int x : {0x01, 0x80, 0xFF}) {
      std::string damaged = bytes;
      damaged[i] = static_cast<char>(static_cast<unsigned char>(damaged[i]) ^ x);
      const VscReadResult r = read_vsc(damaged, "damaged.vsc");
      if (r.image) {
        EXPECT_NE(compile_scene(r.image->image), nullptr);
      } else {
        EXPECT_FALSE(r.error.empty());
      }
    }
  }
}

TEST(VscReader, RefusesAnotherMagicOrVersionOrTrailingBytes) {
  std::string bytes = smiley_vsc();
  std::string magic = bytes;
  magic[0] = 'X';
  EXPECT_NE(read_vsc(magic, "m.vsc").error.find("not a .vsc file"), std::string::npos);
  std::string version = bytes;
  put_u32(version, 8, 2);
  EXPECT_NE(read_vsc(version, "v.vsc").error.find("format version 2"), std::string::npos);
  std::string trailing = bytes + "x";
  EXPECT_FALSE(read_vsc(trailing, "t.vsc").image.has_value());
  put_u32(trailing, 12, static_cast<std::uint32_t>(trailing.size() - vsc::kHeaderBytes));
  EXPECT_FALSE(read_vsc(trailing, "t.vsc").image.has_value());
}

TEST(VscReader, RefusesNumbersOutsideTheirRangesAsTheXmlReaderDoes) {
  Element dot;
  dot.id = "d";
  dot.body = Dot{1, 2, -3, 0.5};  // a radius must be > 0
  EXPECT_NE(read_vsc(write_vsc(one_element(dot)), "r.vsc").error.find("radius"), std::string::npos);
  Element line;
  line.id = "l";
  Line l;
  l.damping = 1.5;  // in (0, 1)
  line.body = l;
  EXPECT_NE(read_vsc(write_vsc(one_element(line)), "l.vsc").error.find("damping"), std::string::npos);
  VscImage canvas;
  canvas.image.width_mm = 0.0;
  EXPECT_NE(read_vsc(write_vsc(canvas), "c.vsc").error.find("width"), std::string::npos);
  VscImage actuator;
  actuator.actuator.q = 1e6;
  EXPECT_NE(read_vsc(write_vsc(actuator), "a.vsc").error.find("q"), std::string::npos);
}

TEST(VscReader, RefusesPolygonsWithTooFewPointsAndOtherShapesWithPoints) {
  Element e;
  e.id = "s";
  Surface s;
  s.shape = SurfaceShape::polygon;
  s.points = {{0, 0}, {1, 1}};
  e.body = s;
  EXPECT_NE(read_vsc(write_vsc(one_element(e)), "p.vsc").error.find("2 points"), std::string::npos);
  s.shape = SurfaceShape::rect;
  s.width_mm = s.height_mm = 1.0;
  s.points = {{0, 0}, {1, 1}, {2, 0}};
  e.body = s;
  EXPECT_NE(read_vsc(write_vsc(one_element(e)), "p.vsc").error.find("rect surface with 3 points"), std::string::npos);
}

TEST(VscReader, RefusesGroupsNestedDeeperThanTheFormatAllows) {
  const auto nested = [](int depth) {
    Element inner;
    inner.id = "d";
    inner.body = Dot{};
    for (int i = 0; i < depth; ++i) {
      Element g;
      g.id = "g" + std::to_string(i);
      g.body = Group{std::nullopt, {inner}};
      inner = g;
    }
    return one_element(inner);
  };
  EXPECT_TRUE(read_vsc(write_vsc(nested(kMaxGroupDepth)), "ok.vsc").image.has_value());
  EXPECT_NE(read_vsc(write_vsc(nested(kMaxGroupDepth + 1)), "deep.vsc").error.find("nest deeper"), std::string::npos);
}

TEST(VscReader, ACountBeyondTheBytesLeftIsRefusedBeforeAnythingIsAllocated) {
  std::string bytes = write_vsc(VscImage{});
  put_u32(bytes, bytes.size() - 4, 1000);  // the element count, last in an empty image: within the limit
  const VscReadResult r = read_vsc(bytes, "count.vsc");
  EXPECT_NE(r.error.find("1000 elements do not fit in the 0 bytes left"), std::string::npos) << r.error;
  put_u32(bytes, bytes.size() - 4, 0xFFFFFFFFu);
  EXPECT_NE(read_vsc(bytes, "count.vsc").error.find("4294967295 elements (limit"), std::string::npos);
}

}  // namespace
}  // namespace vimg
