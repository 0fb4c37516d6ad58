#pragma once
// The G1 Hermite test set shared by tests/constructions/g1_hermite_test.cpp, bench/g1_hermite.cpp and
// tests/reference/g1_clothoid.py: P0 = (0, 0), P1 = (1, 0), θ0 and θ1 uniform in (−π/2, π/2) from
// splitmix64 (seed 20240601), drawn θ0 then θ1 per problem. A draw is the top 53 bits of the
// output as k·2^−53 ∈ [0, 1), mapped to θ = π(k·2^−53 − 1/2); a draw of exactly −π/2 (k = 0) is
// redrawn. The Python generator implements the same steps (and the CSV repeats θ0, θ1 in full
// precision, which the test compares).
#include <cstdint>
#include <numbers>
#include <vector>

namespace lac::test {

struct G1Angles {
  double theta0 = 0, theta1 = 0;
};

inline std::uint64_t splitmix64(std::uint64_t& state) {
  std::uint64_t z = (state += 0x9E3779B97F4A7C15ULL);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

inline constexpr std::uint64_t kG1Seed = 20240601;
inline constexpr int kG1ProblemCount = 2000;

inline std::vector<G1Angles> g1_problem_set(int n = kG1ProblemCount, std::uint64_t seed = kG1Seed) {
  std::uint64_t state = seed;
  const auto draw = [&] {
    for (;;) {
      const std::uint64_t k = splitmix64(state) >> 11;
      if (k != 0) return std::numbers::pi * (static_cast<double>(k) * 0x1.0p-53 - 0.5);
    }
  };
  std::vector<G1Angles> set(static_cast<size_t>(n));
  for (G1Angles& a : set) {
    a.theta0 = draw();
    a.theta1 = draw();
  }
  return set;
}

}  // namespace lac::test
