// geometry/space_closest_point: the global minimum of the distance from points around space curves
// and at their centres of curvature
// (a two-piece G2 curve, a helix-like single piece turning several times) against dense samples
// of the curve (SpaceCurve::sample, 20001 points) with every sampled local minimum polished by
// Brent on frame_at: the search and the reference share the curve's positions, not the method.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <boost/math/tools/minima.hpp>
#include <cmath>
#include <cstdint>
#include <limits>

#include "lac/geometry/space_closest_point.hpp"
#include "tests/support/space_curves.hpp"
#include "tests/support/input_error.hpp"
#include "tests/support/lcg.hpp"

namespace lac {
namespace {

using test::Lcg;

using test::two_pieces;

using test::coil;

TEST(GeometrySpaceClosestPoint, TheCoilTurnsSeveralTimes) {
  EXPECT_GT(coil().pieces()[0].law.turning(20.0), 12.0);
}

std::pair<double, double> reference(const SpaceCurve& c, const Vec3& q, int* minima) {
  const int n = 20001;
  const std::vector<SpacePoint> pts = c.sample(n);
  std::pair<double, double> best{std::numeric_limits<double>::infinity(), 0.0};
  for (int i = 0; i < n; ++i) {
    const double d = (pts[i].p - q).norm();
    if (d < best.first) best = {d, pts[i].s};
    const bool local = (i == 0 || d <= (pts[i - 1].p - q).norm()) && (i + 1 == n || d <= (pts[i + 1].p - q).norm());
    if (!local) continue;
    ++*minima;
    const double lo = pts[std::max(0, i - 1)].s, hi = pts[std::min(n - 1, i + 1)].s;
    std::uintmax_t it = 200;
    const auto m = boost::math::tools::brent_find_minima([&](double s) { return (c.frame_at(s).p - q).squaredNorm(); }, lo, hi, 60, it);
    if (std::sqrt(m.second) < best.first) best = {std::sqrt(m.second), m.first};
  }
  return best;
}

TEST(GeometrySpaceClosestPoint, GlobalMinimumMatchesDenseReference) {
  Lcg rng{4242};
  int checked = 0, several = 0;
  double worst = 0;
  long spans = 0;
  for (const SpaceCurve& c : {two_pieces(), coil()}) {
    ASSERT_TRUE(c.length() > 0);
    Vec3 lo = c.frame_at(0).p, hi = lo;
    for (const SpacePoint& p : c.sample(200)) lo = lo.cwiseMin(p.p), hi = hi.cwiseMax(p.p);
    const Vec3 span = hi - lo;
    for (int i = 0; i < 20; ++i) {
      Vec3 q = lo - 0.2 * span;
      for (int j = 0; j < 3; ++j) q[j] += 1.4 * span[j] * rng.next();
      if (i == 19) q = c.frame_at(0.37 * c.length()).p;  // on the curve
      if (i >= 13 && i < 19) {  // centres of curvature (near the evolute: flat distance, several minima)
        const SpacePoint f = c.frame_at(c.length() * (i - 12) / 7.0);
        q = f.p + f.n / f.kappa;
      }
      const SpaceClosestPoint r = closest_point(c, q);
      ASSERT_EQ(r.status, Status::ok) << r.message;
      int minima = 0;
      const auto [d_ref, s_ref] = reference(c, q, &minima);
      several += minima > 1;
      const double L = c.length(), dd = std::abs(r.distance - d_ref);
      EXPECT_LE(dd, r.error_estimate + 1e-12 * L) << "query " << q.transpose() << " s " << r.s << " s_ref " << s_ref;
      EXPECT_LE((c.frame_at(r.s).p - r.point).norm(), 1e-12 * L);
      EXPECT_NEAR((r.point - q).norm(), r.distance, 1e-14 * L);
      worst = std::max(worst, dd / L);
      spans += r.spans;
      ++checked;
    }
  }
  EXPECT_GE(several, 10);  // 11 at this seed (the coil turning 2.4 times)
  std::printf("space closest point: %d queries on 2 curves (%d with several local minima); worst |d - d_ref|/L = %.2e; "
              "%.0f spans mean\n", checked, several, worst, double(spans) / checked);
}

TEST(GeometrySpaceClosestPoint, BadInput) {
  const SpaceCurve c = two_pieces();
  EXPECT_EQ(test::thrown_parameter([&] { closest_point(c, Vec3(NAN, 0, 0)); }), "query");
  EXPECT_EQ(test::thrown_parameter([&] { closest_point(SpaceCurve{}, Vec3(0, 0, 0)); }), "curve");
  GeometryOptions bad;
  bad.tolerance = 0;
  EXPECT_EQ(test::thrown_parameter([&] { closest_point(c, Vec3(0, 0, 0), bad); }), "tolerance");
}

}  // namespace
}  // namespace lac
