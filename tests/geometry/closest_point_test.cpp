// geometry/closest_point: the global minimum of the distance over spirals turning up to 5 times,
// with query points in and around them and on their evolute (the centres of curvature, where
// the distance function is flat), against dense sampling of the long-double model polished by
// bisection (reference_curve.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <cstdint>

#include "curves.hpp"
#include "lac/geometry/closest_point.hpp"
#include "reference_curve.hpp"
#include "tests/support/input_error.hpp"
#include "tests/support/lcg.hpp"

namespace lac {
namespace {

using test::cld;
using test::ld;

using test::Lcg;

TEST(GeometryClosestPoint, GlobalMinimumMatchesDenseReference) {
  int several_minima = 0, near_evolute = 0, checked = 0;
  double worst_distance = 0, worst_s = 0;
  long spans = 0, most_spans = 0, evaluations = 0;
  for (const PlanarCurve& c : test::test_curves()) {
    const test::RefCurve ref(c, 4000, 0.005L);
    const double L = c.length();
    const BoundingBox box = c.bounding_box();
    std::vector<std::complex<double>> queries;
    Lcg rng{12345};
    const std::complex<double> span = box.hi - box.lo;
    for (int i = 0; i < 25; ++i)
      queries.push_back(box.lo - 0.2 * span + std::complex<double>(1.4 * span.real() * rng.next(), 1.4 * span.imag() * rng.next()));
    // On and near the evolute: p(s) + (1 + ε)/κ N(s).
    for (int i = 1; i <= 6; ++i) {
      const double s = L * i / 7.0;
      const PositionResult p = position_at(c, s);
      const std::complex<double> N = std::complex<double>(0, 1) * std::polar(1.0, p.point.theta);
      for (double eps : {-1e-3, 0.0, 1e-3}) queries.push_back(p.point.position + (1 + eps) / p.point.kappa * N);
    }
    for (size_t qi = 0; qi < queries.size(); ++qi) {
      const std::complex<double> q = queries[qi];
      const ClosestPoint r = closest_point(c, q);
      ASSERT_EQ(r.status, Status::ok) << r.message << " query " << q;
      const test::RefClosest e = test::reference_closest(ref, cld(q.real(), q.imag()));
      ++checked;
      spans += r.spans, most_spans = std::max(most_spans, r.spans), evaluations += r.evaluations;
      if (std::isfinite(double(e.second))) ++several_minima;
      if (qi >= 25) ++near_evolute;
      const double dd = std::abs(r.distance - double(e.d));
      worst_distance = std::max(worst_distance, dd / L);
      EXPECT_LE(dd, 1e-10 * L) << "query " << q;
      EXPECT_LE(dd, r.error_estimate + 1e-13 * L) << "query " << q;
      EXPECT_NEAR(std::abs(r.point - q), r.distance, 1e-14 * L);
      // The point is the curve's at r.s.
      const size_t k = c.segment_at(r.s);
      const cld p = ref.position(k, ref.segs[k].u_of(ld(c.local_s(k, r.s))));
      EXPECT_LE(std::abs(r.point - std::complex<double>(double(p.real()), double(p.imag()))), 1e-11 * L);
      // Where the minimum is unique by a margin, its arc length too (√ of the distance accuracy
      // at worst: the minimum is quadratic, flat on the evolute).
      if (double(e.second - e.d) > 1e-6 * L) {
        worst_s = std::max(worst_s, std::abs(r.s - double(e.s)) / L);
        EXPECT_NEAR(r.s, double(e.s), 1e-4 * L) << "query " << q;
      }
    }
  }
  // The test is about several local minima: most queries have them.
  EXPECT_GE(several_minima, checked / 2);
  EXPECT_EQ(near_evolute, 54);
  std::printf("closest point: %d queries, %d with several local minima; worst |Δd|/L = %.2e, worst |Δs|/L = %.2e; "
              "spans %.0f mean, %ld most; %.0f evaluations mean\n",
              checked, several_minima, worst_distance, worst_s, double(spans) / checked, most_spans, double(evaluations) / checked);
}

TEST(GeometryClosestPoint, PointsOnTheCurveAreAtDistanceZero) {
  const PlanarCurve c = test::clothoid_spiral();
  for (double f : {0.0, 0.123, 0.5, 0.999, 1.0}) {
    const PositionResult p = position_at(c, f * c.length());
    const ClosestPoint r = closest_point(c, p.point.position);
    ASSERT_EQ(r.status, Status::ok);
    EXPECT_LE(r.distance, 1e-12 * c.length());
    EXPECT_NEAR(r.s, f * c.length(), 1e-9 * c.length());
  }
}

TEST(GeometryClosestPoint, CapAndBadInput) {
  // The centre of a circular arc is equidistant from every point: no span can be discarded, so
  // the search ends at its cap with a status that is not usable (and finite numbers).
  const LaSegment arc(LaLaw{-1.0}, 0.0, 1.0, 2.0, 2.0, 0.0, {{0, -1}, 1.0, {1, 0}});  // radius 1/2
  const PlanarCurve c({arc});
  GeometryOptions o;
  o.max_spans = 2000;
  const ClosestPoint r = closest_point(c, {0, -0.5}, o);
  EXPECT_EQ(r.status, Status::max_iterations) << r.message;
  EXPECT_FALSE(usable(r.status));
  EXPECT_TRUE(std::isfinite(r.distance));
  EXPECT_NEAR(r.distance, 0.5, 1e-12);
  EXPECT_LE(r.spans, o.max_spans);
  // The clothoid spiral turns 31 rad: covering it takes 62 spans of 0.5 rad, more than 16.
  o.max_spans = 16;
  const ClosestPoint few = closest_point(test::clothoid_spiral(), {0, 0}, o);
  EXPECT_EQ(few.status, Status::max_iterations);
  EXPECT_NE(few.message.find("max_spans"), std::string::npos) << few.message;
  EXPECT_EQ(test::thrown_parameter([&] { closest_point(c, {NAN, 0}); }), "query");
  GeometryOptions bad;
  bad.tolerance = 0;
  EXPECT_EQ(test::thrown_parameter([&] { closest_point(c, {0, 0}, bad); }), "tolerance");
  bad = {};
  bad.max_spans = 1;
  EXPECT_EQ(test::thrown_parameter([&] { closest_point(c, {0, 0}, bad); }), "max_spans");
  bad = {};
  bad.accept = 1;
  EXPECT_EQ(test::thrown_parameter([&] { closest_point(c, {0, 0}, bad); }), "accept");
  EXPECT_EQ(test::thrown_parameter([&] { closest_point(PlanarCurve{}, {0, 0}); }), "curve");
}

}  // namespace
}  // namespace lac
