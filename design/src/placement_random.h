#pragma once

// Private to vantage::design: the draws of marker placement (docs/math.md §21), written here
// rather than taken from <random>'s distributions, whose algorithms differ between standard
// libraries, so that a seed gives the same sites and baseline with any compiler.

#include <cstdint>
#include <random>

namespace vantage::design::internal {

class PlacementRandom {
 public:
  explicit PlacementRandom(std::uint64_t seed) : engine_(seed) {}

  /// The engine of draw `index` of a run seeded with `seed` (SplitMix64 of both), so that a
  /// draw depends on neither the thread nor the other draws.
  static PlacementRandom for_draw(std::uint64_t seed, std::uint64_t index) {
    std::uint64_t z = seed + 0x9e3779b97f4a7c15ULL * (index + 1);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return PlacementRandom(z ^ (z >> 31));
  }

  /// Uniform on [0, 1) with 53 random bits.
  double uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }

  /// Uniform on {0, ..., n - 1}, n >= 1 (rejection: no modulo bias).
  std::uint64_t index(std::uint64_t n) {
    const std::uint64_t limit = ~std::uint64_t{0} - (~std::uint64_t{0} % n);
    std::uint64_t x = engine_();
    while (x >= limit) x = engine_();
    return x % n;
  }

 private:
  std::mt19937_64 engine_;
};

}  // namespace vantage::design::internal
