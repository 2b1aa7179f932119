// The one SPSC ring: order, capacity, bulk transfers across the wrap, and a two-thread handover
// (run under TSan in CI).
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <thread>
#include <vector>

#include "realtime/spsc_ring.hpp"

namespace vimg {
namespace {

TEST(SpscRing, HandsOverEveryValueInOrderAcrossThreads) {
  SpscRing<std::uint64_t> q(64);
  constexpr std::uint64_t kCount = 200000;
  std::thread producer([&] {
    for (std::uint64_t i = 0; i < kCount;) {
      if (q.push(i)) ++i;
      else std::this_thread::yield();
    }
  });
  std::uint64_t expected = 0;
  while (expected < kCount) {
    if (auto v = q.pop()) {
      ASSERT_EQ(*v, expected);
      ++expected;
    } else {
      std::this_thread::yield();
    }
  }
  producer.join();
  EXPECT_FALSE(q.pop().has_value());
}

TEST(SpscRing, RefusesWhenFullAndRoundsCapacityUpToAPowerOfTwo) {
  SpscRing<int> q(3);
  EXPECT_EQ(q.capacity(), 4u);
  for (int i = 0; i < 4; ++i) EXPECT_TRUE(q.push(i));
  EXPECT_FALSE(q.push(4));
  EXPECT_EQ(q.size(), 4u);
  EXPECT_EQ(q.pop(), 0);
  EXPECT_TRUE(q.push(4));
  for (int i = 1; i <= 4; ++i) EXPECT_EQ(q.pop(), i);
  EXPECT_EQ(q.size(), 0u);
}

TEST(SpscRing, BulkPushAndPopKeepOrderAcrossTheWrapAndStopAtTheLimits) {
  SpscRing<float> ring(8);
  std::array<float, 5> in{1, 2, 3, 4, 5};
  std::array<float, 8> out{};
  EXPECT_EQ(ring.push_some(in), 5u);
  EXPECT_EQ(ring.pop_some(std::span<float>(out.data(), 3)), 3u);  // tail at 3
  EXPECT_EQ(ring.push_some(in), 5u);                              // wraps: 2 + 5 = 7 stored
  EXPECT_EQ(ring.push_some(in), 1u);                              // only one slot left
  EXPECT_EQ(ring.pop_some(out), 8u);
  const std::array<float, 8> expected{4, 5, 1, 2, 3, 4, 5, 1};
  EXPECT_EQ(out, expected);
  EXPECT_EQ(ring.pop_some(out), 0u);
}

TEST(SpscRing, BulkHandoverAcrossThreadsLosesNothing) {
  SpscRing<std::uint32_t> ring(256);
  constexpr std::uint32_t kCount = 300000;
  std::thread producer([&] {
    std::array<std::uint32_t, 37> block{};
    std::uint32_t next = 0;
    while (next < kCount) {
      std::size_t n = 0;
      for (; n < block.size() && next + n < kCount; ++n) block[n] = next + static_cast<std::uint32_t>(n);
      std::span<const std::uint32_t> rest(block.data(), n);
      while (!rest.empty()) {
        rest = rest.subspan(ring.push_some(rest));
        if (!rest.empty()) std::this_thread::yield();
      }
      next += static_cast<std::uint32_t>(n);
    }
  });
  std::vector<std::uint32_t> got;
  std::array<std::uint32_t, 50> out{};
  while (got.size() < kCount) {
    const std::size_t n = ring.pop_some(out);
    got.insert(got.end(), out.begin(), out.begin() + static_cast<std::ptrdiff_t>(n));
    if (n == 0) std::this_thread::yield();
  }
  producer.join();
  for (std::uint32_t i = 0; i < kCount; ++i) ASSERT_EQ(got[i], i);
}

}  // namespace
}  // namespace vimg
