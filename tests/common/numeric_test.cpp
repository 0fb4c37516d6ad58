// common/numeric.hpp: wrap_angle's fast path against std::remainder.
#include "lac/common/numeric.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

namespace {

double reference_wrap(double a) {
  const double r = std::remainder(a, 2.0 * std::numbers::pi);
  return r <= -std::numbers::pi ? r + 2.0 * std::numbers::pi : r;
}

TEST(WrapAngle, EqualsTheRemainderBitForBit) {
  constexpr double pi = std::numbers::pi;
  std::vector<double> a{0.0, -0.0, pi, -pi, 3 * pi, -3 * pi, 2 * pi, -2 * pi, 9.42, -9.42, 9.4247779607693793,
                        std::nextafter(pi, 0.0), std::nextafter(pi, 4.0), std::nextafter(-pi, 0.0), std::nextafter(-pi, -4.0),
                        std::nextafter(3 * pi, 0.0), std::nextafter(-3 * pi, 0.0), 1e300, -1e-300};
  std::mt19937_64 rng(3);
  for (double scale : {1.0, 4.0, 9.5, 30.0, 1e6}) {
    std::uniform_real_distribution<double> u(-scale, scale);
    for (int i = 0; i < 100000; ++i) a.push_back(u(rng));
  }
  for (double x : a) {
    const double w = lac::wrap_angle(x), ref = reference_wrap(x);
    ASSERT_EQ(w, ref) << "a = " << x;
    ASSERT_TRUE(w > -pi && w <= pi) << "a = " << x;
  }
}

}  // namespace
