// geometry/quadratic_geometry: evaluate() of a quadratic LA curve against the mpmath positions of
// tests/reference/quadratic_positions.csv; dκ/ds against central differences of κ(s) and its point
// symmetry past the inflection; offsets; the first cusp against the closed form s(κ = 1/d)
// (QuadraticLaCurve::s_at_kappa, an integral in κ: not the κ(s) inversion the search runs on).
#include <gtest/gtest.h>

#include <cmath>
#include <complex>

#include "lac/geometry/quadratic_geometry.hpp"
#include "tests/support/input_error.hpp"
#include "tests/support/reference_csv.hpp"

namespace lac {
namespace {

TEST(GeometryQuadratic, EvaluateMatchesTheMpmathPositions) {
  const auto t = test::read_reference_csv("quadratic_positions.csv");
  double worst = 0;
  for (size_t i = 0; i < t.rows.size(); ++i) {
    const QuadraticLaCurve c(t.number(i, "alpha"), t.number(i, "gamma"), t.number(i, "lambda"));
    const double s = t.number(i, "s");
    const PlanarEvaluation e = evaluate(c, s);
    ASSERT_TRUE(usable(e.status)) << e.message;
    const std::complex<double> ref(t.number(i, "x"), t.number(i, "y"));
    const double scale = std::max(1.0, std::abs(s));
    EXPECT_LE(std::abs(e.position - ref), 1e-9 * scale) << "row " << i;
    worst = std::max(worst, std::abs(e.position - ref) / scale);
    EXPECT_EQ(e.normal, std::complex<double>(0, 1) * e.tangent);
    EXPECT_EQ(e.kappa, c.kappa_at_s(s));
  }
  std::printf("quadratic evaluate: %zu mpmath positions, worst |Δp|/max(1, |s|) = %.2e\n", t.rows.size(), worst);
}

TEST(GeometryQuadratic, DkappaDsMatchesDifferencesAndPointSymmetry) {
  QuadraticOptions through;
  through.through_inflection = true;
  for (const auto& [a, g, l] : {std::tuple{-1.0, -0.3, 1.0}, {0.5, -0.2, 0.7}, {-3.0, 0.3, 1.0}, {1.5, 0.0, 2.0}}) {
    const QuadraticLaCurve c(a, g, l, through);
    const Interval dom = c.s_domain();
    const double lo = std::isfinite(dom.lo) ? dom.lo : -3.0, hi = std::isfinite(dom.hi) ? dom.hi : 3.0;
    // Not at the inflection (the middle of a symmetric domain), where dκ/ds is infinite.
    for (int i = 1; i < 10; ++i) {
      const double s = lo + (hi - lo) * (i + 0.37) / 10.5, h = 1e-6 * (hi - lo);
      const double fd = (c.kappa_at_s(s + h) - c.kappa_at_s(s - h)) / (2 * h);
      EXPECT_NEAR(dkappa_ds_at(c, s), fd, 1e-5 * (std::abs(fd) + 1e-3)) << "alpha " << a << " gamma " << g << " s " << s;
    }
    if (c.has_inflection()) {  // κ(s_i + t) = −κ(s_i − t): the same dκ/ds on both sides
      const double si = c.s_at_zero_kappa();
      for (double t : {0.1, 0.5}) {
        const double x = t * (si - lo);
        EXPECT_NEAR(dkappa_ds_at(c, si + x), dkappa_ds_at(c, si - x), 1e-9 * std::abs(dkappa_ds_at(c, si - x)));
      }
      EXPECT_EQ(dkappa_ds_at(c, si), -INFINITY);
    }
  }
}

TEST(GeometryQuadratic, OffsetsAndFirstCusp) {
  QuadraticOptions through;
  through.through_inflection = true;
  const QuadraticLaCurve c(-1.0, -0.3, 1.0, through);
  const Interval dom = c.s_domain();
  const double si = c.s_at_zero_kappa(), lo = si - 0.99 * (si - dom.lo), hi = si + 0.99 * (si - dom.lo);
  for (double s : {lo, 0.0, 0.5 * si, si + 0.3}) {
    const OffsetPoint o = offset_at(c, s, 0.2);
    const PlanarEvaluation e = evaluate(c, s);
    EXPECT_EQ(o.position, e.position + 0.2 * e.normal);
    EXPECT_EQ(o.factor, 1 - 0.2 * e.kappa);
  }
  // κ decreases from κ(lo) > 1 through 0 to negative values: d = 0.5 meets κ = 2 (before the
  // inflection), d = −0.5 meets κ = −2 (past it, at the point-symmetric image of s(κ = 2)).
  ASSERT_GT(c.kappa_at_s(lo), 2.0);
  ASSERT_LT(c.kappa_at_s(hi), -2.0);
  const OffsetCusp plus = first_offset_cusp(c, 0.5, lo, hi), minus = first_offset_cusp(c, -0.5, lo, hi);
  ASSERT_TRUE(plus.s && minus.s);
  EXPECT_TRUE(plus.backwards_at_start);
  EXPECT_FALSE(minus.backwards_at_start);
  EXPECT_NEAR(*plus.s, c.s_at_kappa(2.0), 1e-12 * (hi - lo));
  EXPECT_NEAR(*minus.s, 2 * si - c.s_at_kappa(2.0), 1e-12 * (hi - lo));
  // κ(lo) < 1/d: no cusp; d = 0: none.
  EXPECT_FALSE(first_offset_cusp(c, 1e-3, lo, hi).s.has_value());
  EXPECT_FALSE(first_offset_cusp(c, 0.0, lo, hi).s.has_value());
  EXPECT_EQ(test::thrown_parameter([&] { first_offset_cusp(c, 0.5, hi, lo); }), "s1");
  EXPECT_EQ(test::thrown_parameter([&] { first_offset_cusp(c, NAN, lo, hi); }), "d");
  EXPECT_EQ(test::thrown_parameter([&] { dkappa_ds_at(c, 2 * dom.hi); }), "s");
}

}  // namespace
}  // namespace lac
