#pragma once
// Counts heap allocations and frees made by the calling thread while a CountAllocations is alive:
// tests/hal/allocation_counter.cpp replaces the global operator new and delete for this test
// program, gated by a thread_local "armed" flag, so other threads and other code are not counted.
#include <cstddef>

namespace vimg::test {

class CountAllocations {
 public:
  CountAllocations();   // arms the calling thread and zeroes its counts
  ~CountAllocations();  // disarms it
  CountAllocations(const CountAllocations&) = delete;
  CountAllocations& operator=(const CountAllocations&) = delete;

  std::size_t allocations() const;  // operator new calls on this thread since construction
  std::size_t frees() const;        // operator delete calls of a non-null pointer
};

}  // namespace vimg::test
