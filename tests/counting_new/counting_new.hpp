#pragma once
// A counting operator new for the tests that show a path allocates nothing (the real-time loop,
// tests/player/live_allocation_test.cpp; the page's live renderer,
// tests/web_live/web_live_allocation_test.cpp). Linking counting_new.cpp into a test binary
// replaces every form of operator new and delete in it; the count is per thread.
#include <cstdint>

namespace vimg::test {

// Allocations made by the calling thread since it started.
std::uint64_t allocations_on_this_thread() noexcept;

}  // namespace vimg::test
