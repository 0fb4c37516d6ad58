// Quadratic LA curve positions with a proven bound (curves/quadratic/certified_position.hpp):
// against the long-double RKF78 oracle of fuzz/oracle_check.hpp on random curves over their
// drawing range, and through the inflection by the point symmetry of the curve.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "fuzz/oracle_check.hpp"
#include "lac/curves/quadratic/certified_position.hpp"
#include "tests/support/input_error.hpp"

namespace {

using namespace lac;

TEST(QuadraticCertifiedPosition, TheBoundHoldsAgainstTheLongDoubleOracle) {
  std::mt19937_64 g(20261129);
  auto uniform = [&](double a, double b) { return std::uniform_real_distribution<double>(a, b)(g); };
  int checked = 0;
  double worst = 0, worst_bound = 0;
  for (int i = 0; i < 150; ++i) {
    const double alpha = uniform(-3, 4), gamma = uniform(-1, 1), lambda = std::exp(uniform(std::log(0.3), std::log(3.0)));
    const QuadraticLaCurve c(alpha, gamma, lambda);
    const Interval range = c.default_range();
    const double s = uniform(0, 1) < 0.5 ? range.lo : range.hi;
    if (!std::isfinite(s) || !c.s_domain().contains(s)) continue;
    const oracle::QuadraticPoint o = oracle::quadratic_point(alpha, gamma, lambda, s);
    if (!o.ok) continue;
    const CertifiedTangentIntegral q = integrate_quadratic_certified(c, 0.0, s);
    ASSERT_EQ(q.status, Status::ok) << q.message << " alpha " << alpha << " gamma " << gamma << " lambda " << lambda;
    // The oracle's own error: RKF78 at 1e-16 in long double, far below the bounds (1e-13 and up).
    const double err = static_cast<double>(std::abs(oracle::CR(q.value.real(), q.value.imag()) - o.position));
    EXPECT_LE(err, q.error) << "alpha " << alpha << " gamma " << gamma << " lambda " << lambda << " s " << s;
    worst = std::max(worst, err / q.error);
    worst_bound = std::max(worst_bound, q.error / std::abs(s));
    ++checked;
  }
  std::printf("%d arcs: largest error / bound %.3g, largest bound / length %.3g\n", checked, worst, worst_bound);
  EXPECT_GE(checked, 120);
  EXPECT_LE(worst_bound, 1e-10);
}

// Past the inflection the curve is the point-symmetric image: c(s_i + t) = 2c(s_i) − c(s_i − t), so
// ∫_{s_i − t}^{s_i + t} e^{iθ} = 2 ∫_{s_i − t}^{s_i} e^{iθ}; both sides integrated (the left through
// the inflection zone) agree within their bounds.
TEST(QuadraticCertifiedPosition, ThroughTheInflectionByPointSymmetry) {
  std::mt19937_64 g(7);
  auto uniform = [&](double a, double b) { return std::uniform_real_distribution<double>(a, b)(g); };
  int checked = 0;
  for (int i = 0; i < 200 && checked < 40; ++i) {
    QuadraticOptions options;
    options.through_inflection = true;
    const QuadraticLaCurve c(uniform(-3, 4), uniform(-1, -0.05), std::exp(uniform(std::log(0.3), std::log(3.0))), options);
    if (!c.has_inflection()) continue;
    const double si = c.s_at_zero_kappa(), t = std::min(uniform(0.1, 2.0), 0.9 * (si - c.s_domain().lo));
    if (!(t > 0) || !c.s_domain().contains(si - t) || !c.s_domain().contains(si + t)) continue;
    const double a = si - t, b = si + t;  // rounded: the two halves' lengths differ by that much
    const CertifiedTangentIntegral both = integrate_quadratic_certified(c, a, b);
    const CertifiedTangentIntegral half = integrate_quadratic_certified(c, a, si);
    const double asymmetry = std::abs((b - si) - (si - a));
    ASSERT_EQ(both.status, Status::ok) << both.message;
    ASSERT_EQ(half.status, Status::ok) << half.message;
    EXPECT_LE(std::abs(both.value - 2.0 * half.value), both.error + 2 * half.error + asymmetry)
        << "curve " << i << " alpha " << c.alpha() << " gamma " << c.gamma() << " lambda " << c.lambda() << " t " << t << " si " << si;
    EXPECT_LE(both.error, 1e-9 * t);  // also where s_i ~ 1e7 (its rounding enters u)
    ++checked;
  }
  EXPECT_GE(checked, 20);
}

TEST(QuadraticCertifiedPosition, EitherOrderAndBadInput) {
  const QuadraticLaCurve c(-1, -0.3, 1);
  const CertifiedTangentIntegral f = integrate_quadratic_certified(c, -0.5, 0.5), b = integrate_quadratic_certified(c, 0.5, -0.5);
  EXPECT_EQ(f.value, -b.value);
  EXPECT_EQ(test::thrown_parameter([&] { integrate_quadratic_certified(c, 0.0, 1e300); }), "s1");
}

}  // namespace
