#pragma once
// Per-contact shader state, owned by the caller (the player keeps one per finger-primitive
// contact). Storage is inline so that creating, copying and dropping a contact never allocates.
#include <array>
#include <cstddef>
#include <new>
#include <type_traits>

namespace vimg {

class ShaderState {
 public:
  static constexpr std::size_t kCapacityBytes = 256;

  // Starts a fresh state of type T, value-initialized.
  template <class T>
  T& emplace() {
    check<T>();
    return *::new (static_cast<void*>(storage_.data())) T{};
  }
  template <class T>
  T& get() {
    check<T>();
    return *std::launder(reinterpret_cast<T*>(storage_.data()));
  }
  template <class T>
  const T& get() const {
    check<T>();
    return *std::launder(reinterpret_cast<const T*>(storage_.data()));
  }

 private:
  template <class T>
  static constexpr void check() {
    static_assert(sizeof(T) <= kCapacityBytes, "shader state too large");
    static_assert(alignof(T) <= alignof(std::max_align_t), "shader state over-aligned");
    static_assert(std::is_trivially_copyable_v<T> && std::is_trivially_destructible_v<T>,
                  "shader state must be plain data so contacts copy and drop freely");
  }
  alignas(std::max_align_t) std::array<std::byte, kCapacityBytes> storage_{};
};

}  // namespace vimg
