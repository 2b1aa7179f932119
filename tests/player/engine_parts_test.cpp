#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>

#include "fake_shader.hpp"
#include "player/contact_mixer.hpp"
#include "player/scene.hpp"
#include "realtime/soft_limit.hpp"
#include "player/spatial_grid.hpp"

namespace vimg {
namespace {

using test::FakeShader;

TEST(SpatialGrid, FindsExactlyTheBoxesALinearScanFinds) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> pos(0.0, 0.1), size(0.0, 0.004);
  std::vector<Bounds2M> boxes;
  for (int i = 0; i < 5000; ++i) {
    const double x = pos(rng), y = pos(rng);
    boxes.push_back({x, y, x + size(rng), y + size(rng)});
  }
  boxes.push_back({0.0, 0.0, 0.1, 0.1});  // one large box covering everything
  const SpatialGrid grid(boxes);
  for (int q = 0; q < 500; ++q) {
    const double x = pos(rng) * 1.2 - 0.01, y = pos(rng) * 1.2 - 0.01;
    const Bounds2M query{x, y, x + size(rng), y + size(rng)};
    std::set<std::uint32_t> from_grid, from_scan;
    grid.for_each_candidate(query, [&](std::uint32_t i) {
      if (boxes[i].intersects(query)) from_grid.insert(i);
    });
    for (std::uint32_t i = 0; i < boxes.size(); ++i)
      if (boxes[i].intersects(query)) from_scan.insert(i);
    ASSERT_EQ(from_grid, from_scan);
  }
}

TEST(SpatialGrid, VisitsFewCandidatesPerSmallQuery) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> pos(0.0, 1.0);
  std::vector<Bounds2M> boxes;
  for (int i = 0; i < 100000; ++i) {
    const double x = pos(rng), y = pos(rng);
    boxes.push_back({x, y, x + 0.001, y + 0.001});
  }
  const SpatialGrid grid(boxes);
  std::size_t visited = 0;
  for (int q = 0; q < 100; ++q) {
    const double x = pos(rng), y = pos(rng);
    grid.for_each_candidate({x, y, x + 0.0001, y}, [&](std::uint32_t) { ++visited; });
  }
  EXPECT_LT(static_cast<double>(visited) / 100.0, 40.0);  // a handful per query, not a fraction of 100 000
}

std::shared_ptr<Scene> scene_of(std::vector<std::pair<Bounds2M, std::pair<double, int>>> specs,
                                std::vector<const FakeShader*>* out = nullptr) {
  std::vector<ScenePrimitive> prims;
  for (const auto& [box, param] : specs) {
    auto s = std::make_unique<FakeShader>(box, param.first, param.second);
    if (out) out->push_back(s.get());
    prims.push_back({std::move(s), box, "p"});
  }
  return std::make_shared<Scene>(std::move(prims), Vec3{0, 0, 1}, 2.0);
}

FingerStep step_of(double x0, double x1, int finger = 0, std::uint32_t touch = 1) {
  FingerStep f;
  f.finger = finger;
  f.touch_id = touch;
  f.previous_position_m = {x0, 0.0, 0.0};
  f.position_m = {x1, 0.0, 0.0};
  return f;
}

TEST(ContactMixer, SumsContributionsInDriveUnitsAndDropsInactiveContacts) {
  std::vector<const FakeShader*> shaders;
  auto scene = scene_of({{{0.0, -1, 0.01, 1}, {0.6, 0}}, {{0.005, -1, 0.02, 1}, {0.4, 0}}}, &shaders);
  ContactMixer mixer(16);
  mixer.set_scene(scene.get());
  EXPECT_DOUBLE_EQ(mixer.step(std::vector{step_of(-0.001, 0.002)}, 0.0, 1e-3), 0.3);  // 0.6 N / 2 N
  EXPECT_DOUBLE_EQ(mixer.step(std::vector{step_of(0.002, 0.007)}, 0.001, 1e-3), 0.5);
  EXPECT_EQ(mixer.active_contacts(), 2u);
  EXPECT_DOUBLE_EQ(mixer.step(std::vector{step_of(0.007, 0.03)}, 0.002, 1e-3), 0.0);
  EXPECT_EQ(mixer.active_contacts(), 2u);  // the step still overlaps both boxes
  EXPECT_DOUBLE_EQ(mixer.step(std::vector{step_of(0.03, 0.04)}, 0.003, 1e-3), 0.0);
  EXPECT_EQ(mixer.active_contacts(), 0u);
  EXPECT_EQ(shaders[0]->begins.load(), 1);
}

TEST(ContactMixer, ANewCrossingStartsANewContact) {
  std::vector<const FakeShader*> shaders;
  auto scene = scene_of({{{0.0, -1, 0.001, 1}, {1.0, 0}}}, &shaders);
  ContactMixer mixer(16);
  mixer.set_scene(scene.get());
  mixer.step(std::vector{step_of(-0.002, 0.0005)}, 0.0, 1e-3);
  mixer.step(std::vector{step_of(0.0005, 0.003)}, 0.001, 1e-3);  // leaves
  mixer.step(std::vector{step_of(0.003, 0.005)}, 0.002, 1e-3);   // far
  EXPECT_EQ(mixer.active_contacts(), 0u);
  mixer.step(std::vector{step_of(0.005, 0.0005)}, 0.003, 1e-3);  // back in
  EXPECT_EQ(shaders[0]->begins.load(), 2);
}

TEST(ContactMixer, AContactRingsOnAfterItsTouchLifts) {
  auto scene = scene_of({{{0.0, -1, 0.01, 1}, {1.0, 3}}});
  ContactMixer mixer(16);
  mixer.set_scene(scene.get());
  EXPECT_EQ(mixer.step(std::vector{step_of(0.001, 0.002)}, 0.0, 1e-3), 0.5);
  // The touch lifts inside the box: the shader must see the finger leave and ring.
  const std::vector<FingerStep> none;
  for (int i = 0; i < 3; ++i) EXPECT_EQ(mixer.step(none, 0.001 * (i + 1), 1e-3), 0.5) << i;
  EXPECT_EQ(mixer.step(none, 0.004, 1e-3), 0.0);
  EXPECT_EQ(mixer.active_contacts(), 0u);
}

TEST(ContactMixer, EachTouchHasItsOwnContacts) {
  auto scene = scene_of({{{0.0, -1, 0.01, 1}, {0.25, 0}}});
  ContactMixer mixer(16);
  mixer.set_scene(scene.get());
  std::vector<FingerStep> two{step_of(0.001, 0.002, 0, 1), step_of(0.003, 0.004, 1, 2)};
  EXPECT_DOUBLE_EQ(mixer.step(two, 0.0, 1e-3), 0.25);  // finger 1's position is inside too
  EXPECT_EQ(mixer.active_contacts(), 2u);
}

TEST(ContactMixer, AFullPoolRefusesNewContactsWithoutFailing) {
  std::vector<std::pair<Bounds2M, std::pair<double, int>>> specs;
  for (int i = 0; i < 10; ++i) specs.push_back({{0.0, -1, 0.01, 1}, {0.1, 0}});
  auto scene = scene_of(specs);
  ContactMixer mixer(4);
  mixer.set_scene(scene.get());
  EXPECT_NEAR(mixer.step(std::vector{step_of(0.001, 0.002)}, 0.0, 1e-3), 0.2, 1e-12);
  EXPECT_EQ(mixer.active_contacts(), 4u);
  EXPECT_EQ(mixer.refused_contacts(), 6u);
}

TEST(ContactMixer, LinearScanGivesTheSameOutputAsTheGrid) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> pos(0.0, 0.05);
  std::vector<std::pair<Bounds2M, std::pair<double, int>>> specs;
  for (int i = 0; i < 300; ++i) {
    const double x = pos(rng), y = pos(rng) - 0.025;
    specs.push_back({{x, y, x + 0.002, y + 0.03}, {0.01 * (i % 7), i % 5}});
  }
  auto scene = scene_of(specs);
  ContactMixer grid(512), scan(512);
  grid.set_scene(scene.get());
  scan.set_scene(scene.get());
  scan.use_linear_scan(true);
  for (int k = 0; k < 400; ++k) {
    const std::vector<FingerStep> s{step_of(k * 1.25e-4, (k + 1) * 1.25e-4)};
    ASSERT_NEAR(grid.step(s, k * 1e-3, 1e-3), scan.step(s, k * 1e-3, 1e-3), 1e-12) << k;
  }
}

}  // namespace
}  // namespace vimg
