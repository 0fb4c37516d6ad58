// to_bspline of a quadratic LA curve's arc (export/to_bspline_quadratic.cpp, 003): the certified
// bound holds against a dense sampling of the curve by its own evaluator (Gauss–Kronrod at
// 1e-14), on random curves over the ranges of the quadratic tests; the structure of the result.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <random>
#include <vector>

#include "lac/common/error.hpp"
#include "lac/curves/quadratic/quadratic_position.hpp"
#include "lac/export/detail/hermite_bound.hpp"
#include "lac/export/to_bspline.hpp"
#include "lac/geometry/quadratic_geometry.hpp"

namespace lac {
namespace {

struct Measured {
  double deviation = 0;  ///< max |c(s) − b(s)| over the samples
  double reference_error = 0;  ///< the samples' largest error estimate
};

/// `n` samples uniform in s over [s0, s1] (the curve's polyline, Gauss–Kronrod at 1e-14) against
/// the B-spline at the same arc length from s0.
Measured measure(const QuadraticLaCurve& c, double s0, double s1, const BSpline& b, int n) {
  Measured m;
  const auto pts = polyline(c, s0, s1, n, GaussKronrod{.tol = 1e-14});
  for (const PositionResult& p : pts) {
    EXPECT_TRUE(usable(p.status)) << p.message;
    m.deviation = std::max(m.deviation, std::abs(p.point.position - b.point_at(p.point.s - s0)));
    m.reference_error = std::max(m.reference_error, p.error_estimate);
  }
  return m;
}

TEST(QuadraticExport, BoundIsCertifiedOnRandomCurves) {
  std::mt19937_64 rng(20261127);
  std::uniform_real_distribution<double> U(0, 1);
  const int curves = std::getenv("LAC_LONG_TESTS") ? 1000 : 120;
  int ok = 0, not_ok = 0, inflections = 0, skipped = 0, quintic = 0, quintic_monotone = 0;
  std::vector<double> ratios;
  for (int i = 0; i < curves; ++i) {
    const double alpha = -3 + 7 * U(rng), gamma = -1 + 2 * U(rng), lambda = 0.3 * std::pow(10.0, U(rng));
    QuadraticOptions o;
    o.through_inflection = U(rng) < 0.3;
    const QuadraticLaCurve c(alpha, gamma, lambda, o);
    const Interval range = c.default_range();
    const int degree = U(rng) < 0.5 ? 3 : 5;
    const double rel = std::pow(10.0, -3 - 6 * U(rng));  // tolerance 1e-9 … 1e-3 of the length
    const double length = range.hi - range.lo;
    ExportResult r;
    try {
      c.check_s(range.lo, "s0");
      c.check_s(range.hi, "s1");
    } catch (const InputError&) {  // a default range ending on the domain's bound (beyond 1e39): nothing to export
      ++skipped;
      continue;
    }
    if (length > 1e4) {  // nearly straight arcs of length up to 1e9 (κ ≥ 1e-3 · κ(0) far away): slow to sample
      ++skipped;
      continue;
    }
    // Half with the fit, a quarter of all with fits of degree 3 to 8.
    r = to_bspline(c, range.lo, range.hi,
                   {.tolerance = rel * length, .degree = degree, .fit = i % 4 >= 2, .fit_max_degree = i % 8 >= 6 ? 8 : 0});
    SCOPED_TRACE("alpha " + format_number(alpha) + " gamma " + format_number(gamma) + " lambda " + format_number(lambda) +
                 " through_inflection " + std::to_string(o.through_inflection) + " degree " + std::to_string(degree) +
                 " range [" + format_number(range.lo) + ", " + format_number(range.hi) + "]");
    if (r.summary.status != Status::ok) {
      ++not_ok;
      EXPECT_TRUE(r.summary.status == Status::inaccurate || r.summary.status == Status::max_iterations) << r.summary.message;
      continue;
    }
    ++ok;
    const bool inflection =
        o.through_inflection && c.has_inflection() && range.lo < c.s_at_zero_kappa() && c.s_at_zero_kappa() < range.hi;
    inflections += inflection;
    EXPECT_LE(r.info.max_deviation, rel * length);
    if (degree == 5 && r.info.continuity == "G2") {  // quintic spans throughout (the cubic's curvature jumps at knots)
      ++quintic;
      quintic_monotone += r.info.curvature_monotone;
    }
    const Measured m = measure(c, range.lo, range.hi, r.curve, static_cast<int>(std::max<long>(1000, 8 * r.info.spans)));
    EXPECT_LE(m.deviation, r.info.max_deviation + m.reference_error);
    ratios.push_back(m.deviation / r.info.max_deviation);
  }
  std::sort(ratios.begin(), ratios.end());
  ASSERT_FALSE(ratios.empty());
  const double median = ratios[ratios.size() / 2], largest = ratios.back(), smallest = ratios.front();
  std::printf("%d curves certified (%d through an inflection), %d not ok, %d skipped; measured / bound: min %.3g, "
              "median %.3g, max %.3g; curvature monotone on %d of %d G2 quintics\n",
              ok, inflections, not_ok, skipped, smallest, median, largest, quintic_monotone, quintic);
  // Most curves are certified, and the bound is not absurdly loose (the sampling sees a fair part of it).
  EXPECT_GE(ok, curves * 9 / 10);
  EXPECT_GT(median, 1e-3);
}

// The closed-form bounds of |κ^(j)| on a span (export/to_bspline_quadratic.cpp) against κ
// (kappa_at_s), κ' (geometry's dkappa_ds_at) and κ'', κ''' (central differences of κ') sampled
// on the span: never below them, and close to them on short spans.
TEST(QuadraticExport, DerivativeBoundsHoldAndAreTight) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> U(0, 1);
  std::array<double, 4> worst_ratio{1, 1, 1, 1};  // smallest sampled max / bound per order
  int spans = 0;
  for (int i = 0; i < 100; ++i) {
    const QuadraticLaCurve c(-3 + 7 * U(rng), -1 + 2 * U(rng), 0.3 * std::pow(10.0, U(rng)));
    const Interval range = c.default_range();
    if (!std::isfinite(range.hi - range.lo) || range.hi - range.lo > 1e4) continue;
    const double h = (range.hi - range.lo) * 0.01 * (1 + 4 * U(rng));
    const double s0 = range.lo + (range.hi - range.lo - h) * U(rng), s1 = s0 + h;
    const std::array<double, 5> k = detail::quadratic_derivative_bounds(c, s0, s1);
    const double d = 1e-3 * h;
    std::array<double, 4> sampled{};
    for (int j = 0; j <= 40; ++j) {
      const double s = s0 + d + (h - 2 * d) * j / 40.0;
      const double f0 = dkappa_ds_at(c, s), fp = dkappa_ds_at(c, s + d), fm = dkappa_ds_at(c, s - d);
      const std::array<double, 4> v{std::abs(c.kappa_at_s(s)), std::abs(f0), std::abs((fp - fm) / (2 * d)),
                                    std::abs((fp - 2 * f0 + fm) / (d * d))};
      for (size_t o = 0; o < 4; ++o) sampled[o] = std::max(sampled[o], v[o]);
    }
    SCOPED_TRACE("alpha " + format_number(c.alpha()) + " gamma " + format_number(c.gamma()) + " lambda " +
                 format_number(c.lambda()) + " span [" + format_number(s0) + ", " + format_number(s1) + "]");
    // Orders 0, 1 exact up to rounding; 2, 3 carry the differences' O(d²) error.
    for (size_t o = 0; o < 4; ++o) EXPECT_LE(sampled[o], k[o] * (o < 2 ? 1 + 1e-12 : 1 + 1e-4)) << "order " << o;
    ++spans;
    for (size_t o = 0; o < 4; ++o)
      if (k[o] > 0) worst_ratio[o] = std::min(worst_ratio[o], sampled[o] / k[o]);
  }
  std::printf("%d spans; smallest sampled max / bound for |kappa^(j)|, j = 0..3: %.3g %.3g %.3g %.3g\n", spans,
              worst_ratio[0], worst_ratio[1], worst_ratio[2], worst_ratio[3]);
  EXPECT_GE(spans, 90);
  EXPECT_GT(worst_ratio[0], 0.9);
  EXPECT_GT(worst_ratio[1], 0.5);
}

TEST(QuadraticExport, StructureAndContinuity) {
  const QuadraticLaCurve c(-1.0, -0.3, 1.0);
  const Interval range = c.default_range();
  for (int degree : {3, 5}) {
    const ExportResult r = to_bspline(c, range.lo, range.hi, {.tolerance = 1e-7, .degree = degree, .remove_knots = false});
    ASSERT_EQ(r.summary.status, Status::ok) << r.summary.message;
    // Knot removal (the default): fewer control points within the same tolerance, the curvature
    // still monotone.
    const ExportResult reduced = to_bspline(c, range.lo, range.hi, {.tolerance = 1e-7, .degree = degree});
    ASSERT_EQ(reduced.summary.status, Status::ok) << reduced.summary.message;
    EXPECT_LT(reduced.curve.control_points.size(), r.curve.control_points.size());
    EXPECT_LE(reduced.info.max_deviation, 1e-7);
    if (degree == 5) {
      EXPECT_TRUE(reduced.info.curvature_monotone);
    }
    r.curve.validate();
    EXPECT_EQ(r.curve.degree, degree);
    EXPECT_EQ(r.curve.control_points.size(), static_cast<size_t>(degree == 3 ? 2 * r.info.spans + 2 : 3 * r.info.spans + 3));
    EXPECT_EQ(r.info.continuity, degree == 3 ? "G1" : "G2");
    EXPECT_DOUBLE_EQ(r.curve.knots.back(), range.hi - range.lo);
    if (degree == 5) {
      EXPECT_TRUE(r.info.curvature_monotone);
    }
    // The ends: the curve's own positions (quadrature from s = 0).
    const PlanarEvaluation e0 = evaluate(c, range.lo), e1 = evaluate(c, range.hi);
    EXPECT_LT(std::abs(r.curve.point_at(0) - e0.position), 1e-12);
    EXPECT_LT(std::abs(r.curve.point_at(range.hi - range.lo) - e1.position), 1e-12);
    // A tighter tolerance takes more spans; a tolerance below the rounding of the coordinates is inaccurate.
    const ExportResult fine = to_bspline(c, range.lo, range.hi, {.tolerance = 1e-10, .degree = degree, .remove_knots = false});
    EXPECT_GT(fine.info.spans, r.info.spans);
    const ExportResult tiny = to_bspline(c, range.lo, range.hi, {.tolerance = 1e-17, .degree = degree});
    EXPECT_EQ(tiny.summary.status, Status::inaccurate);
  }
}

TEST(QuadraticExport, ThroughTheInflection) {
  // γ < 0: finite inflection where κ' is unbounded; the spans next to it take the cubic's h²|κ|/16.
  QuadraticOptions o;
  o.through_inflection = true;
  const QuadraticLaCurve c(-1.5, -0.3, 0.7, o);
  ASSERT_TRUE(c.has_inflection());
  const Interval range = c.default_range();
  ASSERT_LT(range.lo, c.s_at_zero_kappa());
  ASSERT_GT(range.hi, c.s_at_zero_kappa());
  const ExportResult r = to_bspline(c, range.lo, range.hi, {.tolerance = 1e-6, .degree = 5});
  ASSERT_EQ(r.summary.status, Status::ok) << r.summary.message;
  EXPECT_EQ(r.info.continuity, "G1");  // cubic spans raised to degree 5 at the inflection
  const Measured m = measure(c, range.lo, range.hi, r.curve, 4000);
  EXPECT_LE(m.deviation, r.info.max_deviation + m.reference_error);
}

TEST(QuadraticExport, BadInput) {
  const QuadraticLaCurve c(1.0, 0.5, 1.0);
  EXPECT_THROW(to_bspline(c, 1.0, 1.0), InputError);
  EXPECT_THROW(to_bspline(c, 1.0, 0.0), InputError);
  EXPECT_THROW(to_bspline(c, 0.0, 1.0, {.tolerance = -1}), InputError);
  EXPECT_THROW(to_bspline(c, 0.0, 1.0, {.degree = 4}), InputError);
  const QuadraticLaCurve bounded(1.0, -0.5, 1.0);
  EXPECT_THROW(to_bspline(bounded, 0.0, 2 * bounded.s_at_zero_kappa()), InputError);
}

}  // namespace
}  // namespace lac
