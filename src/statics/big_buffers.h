#pragma once
// A std allocator for the statics solver's large buffers (the block factorisation's values,
// the QP's per-block data): on Linux an allocation of at least kBigBytes is a mapping of its
// own, and a released one is kept for the next solve (at most kCacheBytes of them, the oldest
// given back first). The kernel zeroes every page of a fresh mapping on its first touch: a
// 10,000-block wall's QP touches a few hundred MB, and re-solving a model (the statics panel
// after each edit, a search's many solves) would pay that again every time.
// Smaller allocations, other systems and AddressSanitizer builds go to the aligned operator new.
#include <cstddef>
#include <new>
#include <vector>

namespace corbel::statics {

namespace bigbuffers {
inline constexpr std::size_t kBigBytes = std::size_t(4) << 20;
inline constexpr std::size_t kCacheBytes = std::size_t(256) << 20;
// Under AddressSanitizer every buffer goes through operator new, where ASan guards it.
#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool kMapped = false;
#else
inline constexpr bool kMapped = true;
#endif
// A mapping of at least `bytes` (≥ kBigBytes), a kept one where one fits; throws std::bad_alloc
// when it cannot.
void* allocate(std::size_t bytes);
void release(void* p, std::size_t bytes) noexcept;
// The bytes kept for reuse now (for tests).
std::size_t cachedBytes() noexcept;
}  // namespace bigbuffers

template <typename T>
struct BigBufferAllocator {
  using value_type = T;
  BigBufferAllocator() = default;
  template <typename U>
  BigBufferAllocator(const BigBufferAllocator<U>&) noexcept {}

  T* allocate(std::size_t n) {
    const std::size_t bytes = n * sizeof(T);
    if (bigbuffers::kMapped && bytes >= bigbuffers::kBigBytes) return static_cast<T*>(bigbuffers::allocate(bytes));
    return static_cast<T*>(::operator new(bytes, std::align_val_t(alignof(T) > 16 ? alignof(T) : 16)));
  }
  void deallocate(T* p, std::size_t n) noexcept {
    const std::size_t bytes = n * sizeof(T);
    if (bigbuffers::kMapped && bytes >= bigbuffers::kBigBytes)
      bigbuffers::release(p, bytes);
    else
      ::operator delete(p, std::align_val_t(alignof(T) > 16 ? alignof(T) : 16));
  }
  template <typename U>
  bool operator==(const BigBufferAllocator<U>&) const noexcept {
    return true;
  }
};

template <typename T>
using BigVector = std::vector<T, BigBufferAllocator<T>>;

}  // namespace corbel::statics
