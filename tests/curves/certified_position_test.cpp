// Planar positions with a proven bound (curves/planar/certified_position.hpp) on segments of every
// regime (tests/support/la_segment_draw.hpp), whole and in random parts, against the long-double
// oracle of fuzz/oracle_check.hpp: the error never exceeds the bound plus the oracle's own
// uncertainty. Without a bound (an honest status, error +inf): curvature that grows past what u
// resolves, e.g. α = 3 with q's zero 1e-35 beyond an end (κ ratio 1e15 along the segment).
#include <gtest/gtest.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "fuzz/oracle_check.hpp"
#include "lac/curves/planar/certified_position.hpp"
#include "tests/support/input_error.hpp"
#include "tests/support/la_segment_draw.hpp"

namespace {

using namespace lac;

TEST(CertifiedPosition, TheBoundHoldsAgainstTheLongDoubleOracle) {
  std::mt19937_64 g(1931);
  auto uniform = [&](double a, double b) { return std::uniform_real_distribution<double>(a, b)(g); };
  const double alphas[] = {-3, -2, -1.5, -1, -0.5, -0.3, -0.1, -0.04, -1e-3, -1e-7, 0, 1e-7, 1e-3, 0.04, 0.1, 0.5, 0.99, 1, 1.01, 2, 3};
  int checked = 0, skipped = 0, unbounded = 0;
  double worst = 0, worst_bound = 0;
  std::vector<double> ratios;
  std::string where;
  for (double alpha : alphas) {
    for (int i = 0; i < 50; ++i) {
      const test::Draw d = test::draw(g, alpha, i < 25 ? 30.0 : i < 35 ? 300.0 : i < 44 ? 0.0 : -30.0);
      const LaSegment seg(d.law, d.seg);
      const bool oracle_unfit = alpha != 0 && std::abs(alpha) < 1e-3 && seg.inflection_u().has_value();
      if (std::abs(seg.turning()) > 2e3 || oracle_unfit) {
        ++skipped;
        continue;
      }
      // The whole segment, then a random part of it.
      double u0 = seg.ua(), u1 = seg.ub();
      for (int part = 0; part < 2; ++part) {
        if (part == 1) {
          const double a = uniform(seg.ua(), seg.ub()), b = uniform(seg.ua(), seg.ub());
          u0 = std::min(a, b), u1 = std::max(a, b);
        }
        const CertifiedTangentIntegral c = integrate_tangent_certified(seg, u0, u1);
        const oracle::IntegralL o = oracle::integrate_tangent(oracle::read_segment(seg).seg, u0, u1);
        if (!o.ok) {
          ++skipped;
          continue;
        }
        if (c.status != Status::ok) {  // allowed only as an honest "no bound"
          EXPECT_TRUE(c.status == Status::max_iterations || c.status == Status::numerical_failure) << c.message;
          EXPECT_TRUE(std::isinf(c.error));
          ++unbounded;
          continue;
        }
        ++checked;
        const double err = static_cast<double>(std::abs(oracle::CR(c.value.real(), c.value.imag()) - o.value));
        // The oracle's own uncertainty: its estimate and, for the offset form, its conversion to the
        // plain law in long double (tests/curves/la_segment_kernel_test.cpp).
        const double oracle_law =
            d.law.offset ? 2 * LDBL_EPSILON / std::abs(alpha) * (1 + std::abs(seg.turning())) * (u1 - u0) : 0.0;
        const double ratio = err / (c.error + static_cast<double>(o.error) + oracle_law);
        ratios.push_back(ratio);
        worst_bound = std::max(worst_bound, c.error / (u1 - u0));
        if (ratio > worst) {
          worst = ratio;
          char text[256];
          std::snprintf(text, sizeof text, "alpha %.3g sigma %g qa %.17g qb %.17g ub %.17g u0 %.17g u1 %.17g error %.3g bound %.3g",
                        alpha, d.law.sigma, d.seg.qa, d.seg.qb, d.seg.ub, u0, u1, err, c.error);
          where = text;
        }
      }
    }
  }
  std::sort(ratios.begin(), ratios.end());
  std::cout << checked << " integrals checked, " << unbounded << " without a bound, " << skipped
            << " skipped; error / bound: median " << ratios[ratios.size() / 2] << ", largest " << worst << " (" << where
            << "); largest bound / length " << worst_bound << "\n";
  EXPECT_LE(worst, 1.0) << where;
  EXPECT_GE(checked, 1600);
  EXPECT_LE(unbounded, checked / 50);
  EXPECT_LE(worst_bound, 1e-10);
}

// The user position: the segment's start, scale and rotation applied, against the same oracle.
TEST(CertifiedPosition, UserPositionsHoldTheirBound) {
  const LaLaw law{-1.5, 1.0, false};
  const detail::LinearQ q{0.0, 2.0, law.q_of_kappa(0.4), law.q_of_kappa(-1.3), 0.7};
  const LaSegment seg(law, q, {.start = {3.0, -2.0}, .scale = 2.5, .rotation = std::polar(1.0, 0.3)});
  const oracle::PlacedSegL placed = oracle::read_segment(seg);
  for (const double s : {0.0, 0.1, 1.7, 3.9, seg.length()}) {
    const CertifiedPoint p = position_certified(seg, s);
    ASSERT_EQ(p.status, Status::ok) << p.message;
    const oracle::IntegralL o = oracle::integrate_tangent(placed.seg, placed.seg.ua, static_cast<long double>(seg.u_at(s)));
    ASSERT_TRUE(o.ok);
    const oracle::CR want = placed.start + placed.scale * placed.rotation * o.value;
    const double err = static_cast<double>(std::abs(oracle::CR(p.position.real(), p.position.imag()) - want));
    EXPECT_LE(err, p.error + 2.5 * static_cast<double>(o.error)) << "s " << s;
    EXPECT_LE(p.error, 1e-12 * (1 + s)) << "s " << s;
  }
  // Continued from a known point: the same value within the two bounds.
  const CertifiedPoint mid = position_certified(seg, 1.7);
  const CertifiedPoint end = position_certified(seg, seg.u_at(1.7), mid.position, mid.error, seg.ub());
  const CertifiedPoint direct = position_certified(seg, seg.length());
  EXPECT_LE(std::abs(end.position - direct.position), end.error + direct.error);
  EXPECT_GE(end.error, mid.error);
}

TEST(CertifiedPosition, BadRangesAreInputErrors) {
  const LaSegment seg(LaLaw{-1.0}, detail::LinearQ{0.0, 1.0, 1.0, -2.0, 0.0});
  EXPECT_EQ(test::thrown_parameter([&] { integrate_tangent_certified(seg, 0.6, 0.4); }), "u1");
  EXPECT_EQ(test::thrown_parameter([&] { integrate_tangent_certified(seg, -0.1, 0.4); }), "u0");
  EXPECT_EQ(test::thrown_parameter([&] { integrate_tangent_certified(seg, 0.1, 1.5); }), "u1");
  EXPECT_EQ(test::thrown_parameter([&] { position_certified(seg, 2.0); }), "s");
}

}  // namespace
