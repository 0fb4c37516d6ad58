#pragma once
// A small reproducible random source for tests (64-bit LCG, Knuth's MMIX constants): the same
// draws on every platform and standard library, unlike std::uniform_real_distribution.
#include <cstdint>

namespace lac::test {

struct Lcg {
  std::uint64_t x = 987654321;
  /// Uniform in [0, 1).
  double next() {
    x = x * 6364136223846793005ULL + 1442695040888963407ULL;
    return double(x >> 11) * 0x1.0p-53;
  }
  /// Uniform in [a, b).
  double in(double a, double b) { return a + (b - a) * next(); }
};

}  // namespace lac::test
