// image -> .vsc -> image: the reader builds exactly the image the writer was given (its renderable
// part, storage/vsc/vsc_image.hpp) and the actuator response, for every shipped example with every
// shipped profile, and for random images of every kind.
#include <gtest/gtest.h>

#include <variant>

#include "tests/storage/storage_test_support.hpp"
#include "tests/web/web_test_support.hpp"

namespace vimg {
namespace {

std::size_t count_primitives(const std::vector<Element>& elements) {
  std::size_t n = 0;
  for (const Element& e : elements) {
    if (const auto* g = std::get_if<Group>(&e.body)) {
      n += count_primitives(g->children);
    } else if (!std::holds_alternative<UnknownElement>(e.body)) {
      ++n;
    }
  }
  return n;
}

void expect_round_trip(const VscImage& v, const std::string& what) {
  const std::string bytes = write_vsc(v);
  const VscReadResult back = read_vsc(bytes, what);
  ASSERT_TRUE(back.image.has_value()) << back.error;
  EXPECT_TRUE(back.image->image == renderable_part(v.image)) << what;
  EXPECT_TRUE(back.image->actuator == v.actuator) << what;
  EXPECT_EQ(count_primitives(back.image->image.children), count_primitives(v.image.children)) << what;
  // Writing what was read gives the same bytes: nothing is lost or invented on the way.
  EXPECT_EQ(write_vsc(*back.image), bytes) << what;
}

TEST(VscRoundTrip, EveryShippedExampleWithEveryShippedProfile) {
  const auto examples = test::example_images();
  ASSERT_GE(examples.size(), 10u);
  for (const auto& profile : {"ideal.xml", "lra-175hz-drv2605l.xml", "erm-10mm.xml", "voice-coil-audio.xml"}) {
    const ResponseParams response = test::shipped_response(profile);
    for (const auto& path : examples) {
      const Image image = test::load_example(path);
      ASSERT_FALSE(image.children.empty()) << path;
      expect_round_trip({image, response}, path.string() + " with " + profile);
    }
  }
}

TEST(VscRoundTrip, RandomImagesOfEveryKind) {
  for (unsigned seed = 1; seed <= 300; ++seed) {
    const Image image = test::RandomImages(seed).make(20);
    ResponseParams response;
    response.model = static_cast<ResponseModel>(seed % 4);
    response.resonance_hz = 40.0 + seed;
    response.q = 0.5 + seed * 0.25;
    expect_round_trip({image, response}, "seed " + std::to_string(seed));
  }
}

TEST(VscRoundTrip, KeepsOnlyWhatTheRendererUses) {
  Image image = test::RandomImages(7).make(0);
  image.meta = Meta{};
  image.meta->title = "a title";
  image.extra_attributes.emplace_back("x:layer", "top");
  Element unknown;
  unknown.id = "u";
  unknown.body = UnknownElement{"<x:thing/>"};
  Element dot;
  dot.id = "d";
  dot.body = Dot{1, 2, 3, 0.5};
  dot.extra_attributes.emplace_back("x:note", "n");
  dot.source_line = 12;
  image.children = {unknown, dot};
  const Image kept = renderable_part(image);
  EXPECT_FALSE(kept.meta.has_value());
  EXPECT_TRUE(kept.extra_attributes.empty());
  ASSERT_EQ(kept.children.size(), 1u);
  EXPECT_EQ(kept.children[0].id, "d");
  EXPECT_TRUE(kept.children[0].extra_attributes.empty());
  EXPECT_TRUE(std::get<Dot>(kept.children[0].body) == (Dot{1, 2, 3, 0.5}));
}

}  // namespace
}  // namespace vimg
