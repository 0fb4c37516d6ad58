// The least-squares reduction of the certified export (export/detail/bspline_fit.hpp): the Bézier
// pieces (blossoms) on breaks that are not knots reproduce the B-spline, and the fit's proven distance to the
// Hermite B-spline H is never below the distance measured densely, on random chains, for fits of H's
// degree and of other degrees (3, 7); the fits keep H's end data.
#include <gtest/gtest.h>

#include <cstdio>
#include <random>

#include "lac/export/detail/bspline_fit.hpp"
#include "lac/export/to_bspline.hpp"
#include "tests/export/random_curves.hpp"

namespace {

using namespace lac;

BSpline hermite(const PlanarCurve& c, double tol, int degree) {
  const ExportResult h = to_bspline(c, {.tolerance = tol, .degree = degree, .remove_knots = false});
  EXPECT_TRUE(h.usable()) << h.summary.message;
  return h.curve;
}

TEST(BsplineFit, BezierPiecesByBlossomingReproduceTheCurve) {
  std::mt19937_64 rng(7);
  const PlanarCurve c = test::random_chain(rng);
  for (int p : {3, 5}) {
    const BSpline b = hermite(c, 1e-6 * c.length(), p);
    const double a = b.t_min(), e = b.t_max();
    std::vector<double> breaks{a, a + 0.137 * (e - a), a + 0.3 * (e - a), a + 0.81 * (e - a), e};
    for (double k : b.knots)
      if (k > a && k < e) breaks.push_back(k);
    std::sort(breaks.begin(), breaks.end());
    breaks.erase(std::unique(breaks.begin(), breaks.end()), breaks.end());
    const auto pieces = detail::bezier_pieces_on(p, b.knots, b.control_points, breaks);
    ASSERT_EQ(pieces.size(), breaks.size() - 1);
    for (int i = 0; i <= 400; ++i) {
      const double t = a + (e - a) * i / 400.0;
      // The piece holding t, by de Casteljau.
      size_t j = static_cast<size_t>(std::upper_bound(breaks.begin(), breaks.end(), t) - breaks.begin());
      j = std::min(j == 0 ? 0 : j - 1, pieces.size() - 1);
      std::vector<std::complex<double>> d = pieces[j];
      const double x = (t - breaks[j]) / (breaks[j + 1] - breaks[j]);
      for (int r = 1; r <= p; ++r)
        for (int k = 0; k + r <= p; ++k) d[k] = (1 - x) * d[k] + x * d[k + 1];
      EXPECT_LT(std::abs(d[0] - b.point_at(t)), 1e-12 * c.length()) << "p " << p << " t " << t;
    }
  }
}

TEST(BsplineFit, ProvenDistanceBoundsTheMeasuredOne) {
  std::mt19937_64 rng(20261129);
  int fits = 0;
  double closest = 0;
  for (int i = 0; i < 60; ++i) {
    PlanarCurve c;
    try {
      c = test::random_chain(rng);
    } catch (const InputError&) {
      continue;
    }
    const int p = i % 2 == 0 ? 5 : 3;
    const BSpline h = hermite(c, (i % 3 == 0 ? 1e-4 : 1e-7) * c.length(), p);
    std::vector<double> knots;
    std::vector<int> mult;
    h.distinct_knots(knots, mult);
    const std::vector<double> zero(knots.size() - 1, 0.0);  // H's own bound left out: |B − H| alone
    std::vector<double> joints;
    for (size_t k = 1; k < c.segments().size(); ++k) joints.push_back(c.segment_start(k));
    for (const int q : {p, p == 5 ? 3 : 5, 7})
      for (long n : {1L, 3L, 8L}) {
        const auto f = detail::fit_bspline(p, q, h.knots, h.control_points, knots, zero, joints, n);
        if (!std::isfinite(f.deviation)) continue;
        BSpline b{q, f.knots, f.points, {}};
        b.validate();
        double measured = 0;
        for (int s = 0; s <= 4000; ++s) {
          const double t = h.t_min() + (h.t_max() - h.t_min()) * s / 4000.0;
          measured = std::max(measured, std::abs(b.point_at(t) - h.point_at(t)));
        }
        EXPECT_LE(measured, f.deviation) << "curve " << i << " q " << q << " n " << n;
        closest = std::max(closest, measured / f.deviation);
        // End data: the same end points; at the start the same first and second derivatives (p = 5,
        // G2 end data) or the same tangent direction (p = 3: its length is fitted).
        EXPECT_LT(std::abs(b.control_points.front() - h.control_points.front()), 1e-15 * (1 + c.length()));
        EXPECT_LT(std::abs(b.control_points.back() - h.control_points.back()), 1e-12 * (1 + c.length()));
        std::complex<double> b0, b1, b2, h0, h1, h2;
        detail::start_derivatives(q, b.knots, b.control_points, b0, b1, b2);
        detail::start_derivatives(p, h.knots, h.control_points, h0, h1, h2);
        if (p == 3) b1 /= std::abs(b1), h1 /= std::abs(h1);
        EXPECT_LT(std::abs(b1 - h1), 1e-9 * std::abs(h1)) << "curve " << i << " q " << q << " n " << n;
        if (p == 5) {
          EXPECT_LT(std::abs(b2 - h2), 1e-9 * (std::abs(h2) + 1 / c.length())) << "curve " << i << " q " << q;
        }
        ++fits;
      }
  }
  std::printf("%d fits; largest measured / proven |B - H|: %.6g\n", fits, closest);
  EXPECT_GE(fits, 300);
  EXPECT_GT(closest, 0.5);  // the bound is not loose for nothing
}

}  // namespace
