// geometry/space_intersections: every crossing of a SpaceCurve with random planes, against an
// independent search: dense samples of the curve (SpaceCurve::sample, 20001 points), each sign
// change of the signed distance polished by TOMS 748 on frame_at (the search and the reference
// share the curve's positions, not the method); planes through the osculating plane's normal
// direction at a point touch there; bad input names its parameter.
#include <gtest/gtest.h>

#include <boost/math/tools/toms748_solve.hpp>
#include <cmath>
#include <cstdint>
#include <vector>

#include "lac/geometry/space_intersections.hpp"
#include "tests/support/input_error.hpp"
#include "tests/support/lcg.hpp"
#include "tests/support/space_curves.hpp"

namespace lac {
namespace {

using test::Lcg;

std::vector<double> reference_crossings(const SpaceCurve& c, const std::vector<SpacePoint>& pts, const Vec3& P, const Vec3& n) {
  std::vector<double> out;
  const auto h = [&](double s) { return n.dot(c.frame_at(s).p - P); };
  for (size_t i = 0; i + 1 < pts.size(); ++i) {
    const double a = n.dot(pts[i].p - P), b = n.dot(pts[i + 1].p - P);
    if (a == 0) out.push_back(pts[i].s);
    if (!((a < 0 && b > 0) || (a > 0 && b < 0))) continue;
    std::uintmax_t it = 200;
    const auto r = boost::math::tools::toms748_solve(h, pts[i].s, pts[i + 1].s, a, b,
                                                     boost::math::tools::eps_tolerance<double>(50), it);
    out.push_back(0.5 * (r.first + r.second));
  }
  return out;
}

TEST(GeometrySpaceIntersectPlane, AllCrossingsMatchTheDenseReference) {
  Lcg rng{8642};
  int planes = 0, total = 0, most = 0;
  double worst = 0;
  for (const SpaceCurve& c : {test::two_pieces(), test::coil()}) {
    const std::vector<SpacePoint> pts = c.sample(20001);
    Vec3 lo = pts[0].p, hi = pts[0].p;
    for (const SpacePoint& x : pts) lo = lo.cwiseMin(x.p), hi = hi.cwiseMax(x.p);
    const double L = c.length();
    for (int k = 0; k < 12; ++k) {
      // Planes through a random point of the bounding box; every third through the coil's axis
      // direction (z), which it crosses once a turn.
      const Vec3 P = lo + (hi - lo).cwiseProduct(Vec3(rng.next(), rng.next(), rng.next()));
      const Vec3 n = k % 3 == 0 ? Vec3(rng.in(-1, 1), rng.in(-1, 1), 0.05) : Vec3(rng.in(-1, 1), rng.in(-1, 1), rng.in(-1, 1));
      const Vec3 u = n.normalized();
      const std::vector<double> expected = reference_crossings(c, pts, P, u);
      const SpaceIntersections x = intersect_plane(c, P, n);
      ASSERT_EQ(x.status, Status::ok) << x.message;
      // Sampling can miss a pair of crossings closer than the sample spacing (and a touch): the
      // library's list holds the reference's, and its extra points come in such close pairs.
      size_t j = 0;
      for (const double se : expected) {
        while (j < x.points.size() && x.points[j].s < se - 1e-9 * L) ++j;
        ASSERT_LT(j, x.points.size()) << "crossing at s = " << se << " missing";
        EXPECT_NEAR(x.points[j].s, se, 1e-9 * L);
        worst = std::max(worst, std::abs(x.points[j].s - se) / L);
        EXPECT_LE(x.points[j].residual, 1e-12 * L);
        EXPECT_NEAR(std::abs(u.dot(x.points[j].point - P)), x.points[j].residual, 1e-15 * L);
        EXPECT_LE((c.frame_at(x.points[j].s).p - x.points[j].point).norm(), 1e-12 * L);
        ++j;
      }
      EXPECT_EQ(x.points.size(), expected.size()) << "extra points";
      for (size_t i = 1; i < x.points.size(); ++i) EXPECT_LT(x.points[i - 1].s, x.points[i].s);
      total += static_cast<int>(expected.size());
      most = std::max(most, static_cast<int>(expected.size()));
      ++planes;
    }
  }
  EXPECT_GE(total, 20);  // the draw (fixed seed) gives 22, up to 3 on one plane (the coil turns 2.4 times)
  EXPECT_GE(most, 3);
  std::printf("space intersect_plane: %d planes on 2 curves, %d crossings (most %d on one plane); worst |s - s_ref|/L = %.2e\n",
              planes, total, most, worst);
}

TEST(GeometrySpaceIntersectPlane, TheOsculatingPlanesNormalDirectionGivesATouch) {
  // The plane through p(s*) spanned by T(s*) and B(s*) (normal N(s*)): h(s) = N·(p(s) − p(s*)) ≈
  // κ (s − s*)² / 2 ≥ 0 near s*, a touch there.
  for (const SpaceCurve& c : {test::two_pieces(), test::coil()}) {
    const double L = c.length();
    for (const double f : {0.23, 0.61, 0.87}) {
      const double s = f * L;
      const SpacePoint p = c.frame_at(s);
      const SpaceIntersections x = intersect_plane(c, p.p, p.n);
      ASSERT_EQ(x.status, Status::ok) << x.message;
      int touches = 0;
      for (const SpaceIntersection& y : x.points)
        if (y.kind == IntersectionKind::tangent && std::abs(y.s - s) < 1e-4 * L) ++touches;
      EXPECT_EQ(touches, 1) << "s* = " << s;
      const auto it = std::find_if(x.points.begin(), x.points.end(), [&](const SpaceIntersection& y) { return std::abs(y.s - s) < 1e-4 * L; });
      ASSERT_NE(it, x.points.end());
      EXPECT_NEAR(it->s, s, 1e-4 * L);  // a touch fixes s to about √tolerance × length
      EXPECT_LE(it->residual, 1e-10 * L);
    }
  }
}

TEST(GeometrySpaceIntersectPlane, BadInputNamesItsParameter) {
  const SpaceCurve c = test::two_pieces();
  EXPECT_EQ(test::thrown_parameter([&] { intersect_plane(c, Vec3(0, 0, 0), Vec3(0, 0, 0)); }), "normal");
  EXPECT_EQ(test::thrown_parameter([&] { intersect_plane(c, Vec3(0, std::nan(""), 0), Vec3(0, 0, 1)); }), "point");
  GeometryOptions o;
  o.max_spans = 3;
  EXPECT_EQ(test::thrown_parameter([&] { intersect_plane(c, Vec3(0, 0, 0), Vec3(0, 0, 1), o); }), "max_spans");
  // A cap ends with a status, the points found before it kept.
  o.max_spans = 16;
  const SpaceIntersections x = intersect_plane(test::coil(), Vec3(0, 0, 0), Vec3(1, 0, 0.01), o);
  EXPECT_EQ(x.status, Status::max_iterations) << x.message;
}

}  // namespace
}  // namespace lac
