#include "statics/huge_pages.h"

#include <cstdint>
#include <cstdlib>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace corbel::statics::hugepages {

namespace {
constexpr std::size_t kHugePage = std::size_t(2) << 20;
std::size_t rounded(std::size_t bytes) { return (bytes + kHugePage - 1) / kHugePage * kHugePage; }
}  // namespace

#if defined(__linux__)

void* allocate(std::size_t bytes) {
  const std::size_t size = rounded(bytes);
  // Map one huge page more than needed and trim both ends to a 2 MiB boundary.
  void* raw = mmap(nullptr, size + kHugePage, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (raw == MAP_FAILED) throw std::bad_alloc();
  const auto start = reinterpret_cast<std::uintptr_t>(raw);
  const std::uintptr_t aligned = (start + kHugePage - 1) / kHugePage * kHugePage;
  if (aligned > start) munmap(raw, aligned - start);
  const std::uintptr_t end = start + size + kHugePage, alignedEnd = aligned + size;
  if (end > alignedEnd) munmap(reinterpret_cast<void*>(alignedEnd), end - alignedEnd);
  void* p = reinterpret_cast<void*>(aligned);
#if defined(MADV_HUGEPAGE)
  madvise(p, size, MADV_HUGEPAGE);  // advice only: without huge pages the mapping still works
#endif
  return p;
}

void release(void* p, std::size_t bytes) noexcept {
  if (p) munmap(p, rounded(bytes));
}

void advise(void* p, std::size_t bytes) noexcept {
#if defined(MADV_HUGEPAGE)
  if (!p || bytes < kHugeBytes) return;
  const auto start = reinterpret_cast<std::uintptr_t>(p);
  const std::uintptr_t first = (start + kHugePage - 1) / kHugePage * kHugePage;
  const std::uintptr_t last = (start + bytes) / kHugePage * kHugePage;
  if (last > first) madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE);
#else
  (void)p;
  (void)bytes;
#endif
}

#else

void* allocate(std::size_t bytes) {
  void* p = ::operator new(bytes, std::align_val_t(64));
  return p;
}

void release(void* p, std::size_t) noexcept { ::operator delete(p, std::align_val_t(64)); }

void advise(void*, std::size_t) noexcept {}

#endif

}  // namespace corbel::statics::hugepages
