// Round-trip properties over seeded random images (spec sections 1 and 2, "Round trip"):
// XML -> image, PNG -> image and XML -> PNG -> XML give back what went in.
#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "storage/image_io.hpp"
#include "storage_test_support.hpp"

namespace vimg {
namespace {

constexpr unsigned kSeeds = 200;

TEST(RoundTripProperty, XmlTextGivesBackTheSameImage) {
  for (unsigned seed = 1; seed <= kSeeds; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const Image image = test::RandomImages(seed).make();
    const std::string xml = write_image_xml(image);
    const LoadResult loaded = parse_image_xml(xml, "random.vimg");
    ASSERT_TRUE(loaded.ok()) << (loaded.diagnostics.empty() ? xml : loaded.diagnostics[0].to_string());
    EXPECT_EQ(*loaded.image, image) << xml;
    EXPECT_EQ(write_image_xml(*loaded.image), xml) << "saving a loaded canonical file changes its bytes";
  }
}

TEST(RoundTripProperty, XmlFileGivesBackTheSameImage) {
  test::TempDir dir("xml_rt");
  for (unsigned seed = 1; seed <= 40; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const Image image = test::RandomImages(seed).make();
    const auto path = dir / ("random" + std::to_string(seed) + ".vimg");
    ASSERT_FALSE(save_image_file(image, path).has_value());
    const LoadResult loaded = load_image_file(path);
    ASSERT_TRUE(loaded.ok());
    EXPECT_EQ(*loaded.image, image);
  }
}

TEST(RoundTripProperty, PngFileGivesBackTheSameImage) {
  test::TempDir dir("png_rt");
  for (unsigned seed = 1; seed <= 40; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const Image image = test::RandomImages(seed).make();
    const auto path = dir / ("random" + std::to_string(seed) + ".png");
    SaveOptions options;
    options.scale_px_per_mm = 1.0 + seed % 3;
    ASSERT_FALSE(save_image_file(image, path, options).has_value());
    const LoadResult loaded = load_image_file(path);
    ASSERT_TRUE(loaded.ok()) << (loaded.diagnostics.empty() ? "" : loaded.diagnostics[0].to_string());
    EXPECT_EQ(*loaded.image, image);
  }
}

TEST(RoundTripProperty, XmlThroughPngBackToXmlKeepsTheBytes) {
  test::TempDir dir("xml_png_xml");
  for (unsigned seed = 100; seed < 130; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const Image image = test::RandomImages(seed).make();
    const auto xml_in = dir / "in.vimg";
    const auto png = dir / "mid.png";
    const auto xml_out = dir / "out.vimg";
    ASSERT_FALSE(save_image_file(image, xml_in).has_value());
    const LoadResult a = load_image_file(xml_in);
    ASSERT_TRUE(a.ok());
    ASSERT_FALSE(save_image_file(*a.image, png, {1.5}).has_value());
    const LoadResult b = load_image_file(png);
    ASSERT_TRUE(b.ok());
    ASSERT_FALSE(save_image_file(*b.image, xml_out).has_value());
    EXPECT_EQ(test::read_text_file(xml_out), test::read_text_file(xml_in));
  }
}

TEST(RoundTripProperty, WriterGivesEveryElementAUniqueIdOnce) {
  for (unsigned seed = 1; seed <= 50; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    Image image = test::RandomImages(seed).make();
    // Drop every other id, and make one kept id look like a generated one to force a collision.
    int n = 0;
    std::function<void(std::vector<Element>&)> strip = [&](std::vector<Element>& elements) {
      for (Element& e : elements) {
        if (std::holds_alternative<UnknownElement>(e.body)) continue;
        if (n++ % 2 == 0) e.id.clear();
        if (n == 2) e.id = "dot1";
        if (auto* g = std::get_if<Group>(&e.body)) strip(g->children);
      }
    };
    strip(image.children);
    const LoadResult loaded = parse_image_xml(write_image_xml(image), "ids.vimg");
    ASSERT_TRUE(loaded.ok()) << "assigned ids must be valid and unique";
    std::function<void(const std::vector<Element>&)> check = [&](const std::vector<Element>& elements) {
      for (const Element& e : elements) {
        if (!std::holds_alternative<UnknownElement>(e.body)) {
          EXPECT_FALSE(e.id.empty());
        }
        if (const auto* g = std::get_if<Group>(&e.body)) check(g->children);
      }
    };
    check(loaded.image->children);
    EXPECT_EQ(write_image_xml(*loaded.image), write_image_xml(image)) << "ids are assigned deterministically";
  }
}

}  // namespace
}  // namespace vimg
