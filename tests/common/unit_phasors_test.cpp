// cos and sin of a quadrature panel's nodes in batches (common/detail/unit_phasors.hpp) against
// long double, and independent of how the angles are grouped.
#include "lac/common/detail/unit_phasors.hpp"

#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <random>
#include <vector>

namespace {

TEST(UnitPhasors, WithinFourUlpOfOneOfTheLongDoubleValues) {
  // The kernels' phases: up to a few thousand radians (256 panels of 12 rad plus the end angles).
  std::mt19937_64 rng(7);
  std::vector<double> phi;
  for (double scale : {1e-8, 1.0, 3.2, 40.0, 1e4}) {
    std::uniform_real_distribution<double> u(-scale, scale);
    for (int i = 0; i < 20000; ++i) phi.push_back(u(rng));
  }
  for (double x : {0.0, -0.0, 1.5707963267948966, 3.141592653589793, -6.283185307179586}) phi.push_back(x);
  std::vector<double> c(phi.size()), s(phi.size());
  lac::detail::unit_phasors(phi.data(), phi.size(), c.data(), s.data());
  double worst = 0;
  for (size_t k = 0; k < phi.size(); ++k) {
    const long double x = phi[k];
    worst = std::max({worst, static_cast<double>(std::fabs(c[k] - std::cos(x))),
                      static_cast<double>(std::fabs(s[k] - std::sin(x)))});
  }
  // Absolute error: what the kernel's sums see (|e^{iφ}| = 1); libmvec documents 4 ulp.
  EXPECT_LE(worst, 4 * DBL_EPSILON) << lac::detail::unit_phasors_method();
  RecordProperty("method", std::string(lac::detail::unit_phasors_method()));
  RecordProperty("worst_abs_error", std::to_string(worst));
}

TEST(UnitPhasors, AValueDoesNotDependOnItsBatch) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-20, 20);
  std::vector<double> phi(23);
  for (double& x : phi) x = u(rng);
  std::vector<double> c_all(phi.size()), s_all(phi.size());
  lac::detail::unit_phasors(phi.data(), phi.size(), c_all.data(), s_all.data());
  for (size_t n = 1; n <= 5; ++n)
    for (size_t k = 0; k + n <= phi.size(); k += n) {
      double c[5], s[5];
      lac::detail::unit_phasors(phi.data() + k, n, c, s);
      for (size_t j = 0; j < n; ++j) {
        EXPECT_EQ(c[j], c_all[k + j]) << "batch of " << n << " at " << k + j;
        EXPECT_EQ(s[j], s_all[k + j]) << "batch of " << n << " at " << k + j;
      }
    }
}

}  // namespace
