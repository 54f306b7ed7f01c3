#include "statics/big_buffers.h"

#include <algorithm>
#include <cstdint>
#include <mutex>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace corbel::statics::bigbuffers {

namespace {
constexpr std::size_t kPage = std::size_t(64) << 10;
std::size_t rounded(std::size_t bytes) { return (bytes + kPage - 1) / kPage * kPage; }
}  // namespace

#if defined(__linux__)

namespace {
struct Mapping {
  void* p;
  std::size_t size;
};
// Released mappings, oldest first, and their bytes. Few (kCacheBytes / kBigBytes at most).
std::mutex cacheMutex;
std::vector<Mapping> cache;
std::size_t cached = 0;

// A kept mapping of at least `size` bytes and at most twice that, cut to `size`; null if none.
void* reuse(std::size_t size) {
  std::lock_guard<std::mutex> lock(cacheMutex);
  auto best = cache.end();
  for (auto it = cache.begin(); it != cache.end(); ++it)
    if (it->size >= size && it->size <= 2 * size && (best == cache.end() || it->size < best->size)) best = it;
  if (best == cache.end()) return nullptr;
  const Mapping m = *best;
  cache.erase(best);
  cached -= m.size;
  if (m.size > size) munmap(static_cast<char*>(m.p) + size, m.size - size);
  return m.p;
}
}  // namespace

void* allocate(std::size_t bytes) {
  const std::size_t size = rounded(bytes);
  if (void* p = reuse(size)) return p;
  void* p = mmap(nullptr, size, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (p == MAP_FAILED) throw std::bad_alloc();
  return p;
}

void release(void* p, std::size_t bytes) noexcept {
  if (!p) return;
  const std::size_t size = rounded(bytes);
  std::vector<Mapping> drop;
  {
    std::lock_guard<std::mutex> lock(cacheMutex);
    if (size <= kCacheBytes) {
      try {
        cache.push_back({p, size});
        cached += size;
        p = nullptr;
      } catch (...) {  // no room to note it: given back below
      }
    }
    while (cached > kCacheBytes && !cache.empty()) {
      drop.push_back(cache.front());
      cached -= cache.front().size;
      cache.erase(cache.begin());
    }
  }
  if (p) munmap(p, size);
  for (const Mapping& m : drop) munmap(m.p, m.size);
}

std::size_t cachedBytes() noexcept {
  std::lock_guard<std::mutex> lock(cacheMutex);
  return cached;
}

#else

void* allocate(std::size_t bytes) { return ::operator new(bytes, std::align_val_t(64)); }
void release(void* p, std::size_t) noexcept { ::operator delete(p, std::align_val_t(64)); }
std::size_t cachedBytes() noexcept { return 0; }

#endif

}  // namespace corbel::statics::bigbuffers
