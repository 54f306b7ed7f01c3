#pragma once
// A std allocator for the statics solver's large buffers (the block factorisation's values,
// the QP's per-block data): on Linux an allocation of at least kHugeBytes is mapped on its own,
// aligned to 2 MiB and marked MADV_HUGEPAGE, so the kernel backs it with transparent huge pages
// where it allows them ("madvise" mode). A 10,000-block wall's QP touches several hundred MB
// once; with 4 KiB pages the first-touch page faults cost about as much as the arithmetic.
// Smaller allocations, other systems and AddressSanitizer builds go to the aligned operator new.
#include <cstddef>
#include <new>
#include <vector>

namespace corbel::statics {

namespace hugepages {
inline constexpr std::size_t kHugeBytes = std::size_t(4) << 20;
// Under AddressSanitizer every buffer goes through operator new, where ASan guards it.
#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool kMapped = false;
#else
inline constexpr bool kMapped = true;
#endif
// Maps `bytes` (≥ kHugeBytes) as described above; throws std::bad_alloc when it cannot.
void* allocate(std::size_t bytes);
void release(void* p, std::size_t bytes) noexcept;
// Asks for huge pages on the whole 2 MiB pages inside [p, p + bytes) of memory allocated
// elsewhere (Eigen's vectors and sparse matrices, which take no allocator), before it is first
// written. Advice only: does nothing under kHugeBytes, on other systems, or where refused.
void advise(void* p, std::size_t bytes) noexcept;
}  // namespace hugepages

template <typename T>
struct HugePageAllocator {
  using value_type = T;
  HugePageAllocator() = default;
  template <typename U>
  HugePageAllocator(const HugePageAllocator<U>&) noexcept {}

  T* allocate(std::size_t n) {
    const std::size_t bytes = n * sizeof(T);
    if (hugepages::kMapped && bytes >= hugepages::kHugeBytes) return static_cast<T*>(hugepages::allocate(bytes));
    return static_cast<T*>(::operator new(bytes, std::align_val_t(alignof(T) > 16 ? alignof(T) : 16)));
  }
  void deallocate(T* p, std::size_t n) noexcept {
    const std::size_t bytes = n * sizeof(T);
    if (hugepages::kMapped && bytes >= hugepages::kHugeBytes)
      hugepages::release(p, bytes);
    else
      ::operator delete(p, std::align_val_t(alignof(T) > 16 ? alignof(T) : 16));
  }
  template <typename U>
  bool operator==(const HugePageAllocator<U>&) const noexcept {
    return true;
  }
};

template <typename T>
using BigVector = std::vector<T, HugePageAllocator<T>>;

}  // namespace corbel::statics
