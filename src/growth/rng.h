#pragma once
// The growth kernel's random numbers: SplitMix64, so a seed gives the same run on every
// platform and standard library (std distributions are not specified bit for bit).
#include <cstdint>

namespace corbel::growth {

class Rng {
 public:
  explicit Rng(std::uint64_t seed) : s_(seed) {}
  std::uint64_t next() {
    std::uint64_t z = (s_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  double uniform() { return double(next() >> 11) * 0x1.0p-53; }  // [0, 1)
  int below(int n) { return int(uniform() * n); }                // [0, n)

 private:
  std::uint64_t s_;
};

}  // namespace corbel::growth
