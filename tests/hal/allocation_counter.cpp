#include "tests/hal/allocation_counter.hpp"

#include <cstdlib>
#include <new>

namespace vimg::test {
namespace {

thread_local bool t_armed = false;
thread_local std::size_t t_allocations = 0;
thread_local std::size_t t_frees = 0;

}  // namespace

CountAllocations::CountAllocations() {
  t_allocations = 0;
  t_frees = 0;
  t_armed = true;
}

CountAllocations::~CountAllocations() { t_armed = false; }

std::size_t CountAllocations::allocations() const { return t_allocations; }
std::size_t CountAllocations::frees() const { return t_frees; }

namespace {

void* allocate(std::size_t size) {
  if (t_armed) ++t_allocations;
  if (void* block = std::malloc(size == 0 ? 1 : size)) return block;
  throw std::bad_alloc();
}

void release(void* block) noexcept {
  if (block == nullptr) return;
  if (t_armed) ++t_frees;
  std::free(block);
}

}  // namespace
}  // namespace vimg::test

// The replaceable global forms without alignment; the aligned ones keep the library's own pair.
void* operator new(std::size_t size) { return vimg::test::allocate(size); }
void* operator new[](std::size_t size) { return vimg::test::allocate(size); }
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
  try {
    return vimg::test::allocate(size);
  } catch (...) {
    return nullptr;
  }
}
void* operator new[](std::size_t size, const std::nothrow_t&) noexcept {
  try {
    return vimg::test::allocate(size);
  } catch (...) {
    return nullptr;
  }
}
void operator delete(void* block) noexcept { vimg::test::release(block); }
void operator delete[](void* block) noexcept { vimg::test::release(block); }
void operator delete(void* block, std::size_t) noexcept { vimg::test::release(block); }
void operator delete[](void* block, std::size_t) noexcept { vimg::test::release(block); }
void operator delete(void* block, const std::nothrow_t&) noexcept { vimg::test::release(block); }
void operator delete[](void* block, const std::nothrow_t&) noexcept { vimg::test::release(block); }
